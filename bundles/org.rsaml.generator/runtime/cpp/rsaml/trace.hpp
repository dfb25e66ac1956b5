/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The run's trace: one line per event on standard output.
#pragma once

#include <string>

#include "rsaml/clock.hpp"

namespace rsaml {

/**
 * One line per event on standard output, after the milliseconds since the start of the run. A line is queued, never
 * written by the thread that traces it: a writer thread of the default priority writes the queue out, so that a slow
 * or full pipe never stalls a release (rsaml/tracequeue.hpp). A line that finds the queue full is dropped, and the
 * writer says how many in a line of its own ("trace dropped N lines ...").
 */
class Trace {
 public:
  static void configure(bool enabled, Clock::time_point start);
  static bool enabled();
  static void line(const std::string& text);
  /** A line of the run's report (deadline misses, overruns): printed even when the trace is off. */
  static void report(const std::string& text);
  /** A line the run closes with (the summary), by a thread no release waits for: it waits for room rather than be dropped. */
  static void closing(const std::string& text);
  /** When lines were dropped so far, the closing line that says how many in all (none when none was). */
  static void closing_dropped();
  /** Waits until every line so far is written and flushed. */
  static void flush();
};

}  // namespace rsaml
