/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The run's trace: one line per event on standard output.
#pragma once

#include <string>

#include "rsaml/clock.hpp"

namespace rsaml {

/** One line per event on standard output, after the milliseconds since the start of the run. */
class Trace {
 public:
  static void configure(bool enabled, Clock::time_point start);
  static bool enabled();
  static void line(const std::string& text);
  /** A line of the run's report (deadline misses, overruns, the summary): printed even when the trace is off. */
  static void report(const std::string& text);
  static void flush();
};

}  // namespace rsaml
