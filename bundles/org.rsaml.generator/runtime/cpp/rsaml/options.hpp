/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The command line of a generated program.
#pragma once

#include "rsaml/clock.hpp"

namespace rsaml {

/** The command line of a generated program. */
struct Options {
  long long run_for_ms = -1;  // negative: until interrupted (Ctrl-C, SIGTERM)
  bool trace = true;
  bool realtime = true;
  /** Percent of its modeled execution time each timed job first consumes on the CPU (0: none). */
  long long busy_work_percent = 0;
  bool exit = false;  // --help or a bad argument: exit with status
  int status = 0;
};

Options parse_options(int argc, char** argv, const char* program);

}  // namespace rsaml
