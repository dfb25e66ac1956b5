/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A check of the trace's queue (CppRuntimeTest): lines posted faster than standard output is read fill the pipe, then the
// queue (some are dropped); a closing line waits for room; flush() then returns once every line is written. The test
// reads nothing for a while, then everything, and expects the program to end, having said "flushed" on standard error.
#include <cstdio>
#include <string>

#include "rsaml/tracequeue.hpp"

int main() {
  static rsaml_trace::TraceQueue queue;
  const std::string text(100, 'x');
  for (int i = 0; i < 20000; ++i) {
    queue.post(text);
  }
  queue.post_waiting("closing line");
  queue.post_dropped_in_all();
  queue.flush();
  std::fprintf(stderr, "flushed\n");
  return 0;
}
