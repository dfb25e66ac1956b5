/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The run's trace on standard output, through a queue and its writer thread (rsaml/tracequeue.hpp), and durations as it
// says them.
#include "rsaml/trace.hpp"

#include <atomic>
#include <cstdio>

#include "rsaml/internal.hpp"
#include "rsaml/tracequeue.hpp"

namespace rsaml {

namespace {

std::atomic<bool> trace_enabled{true};

/** The run's one queue; made by the first line, or by configure() at the start of the run, before any release thread. */
rsaml_trace::TraceQueue& queue() {
  static rsaml_trace::TraceQueue lines;
  return lines;
}

}  // namespace

std::string internal::millis(Nanos t) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ms", static_cast<double>(t.count()) / 1e6);
  return text;
}

void Trace::configure(bool enabled, Clock::time_point start) {
  trace_enabled = enabled;
  queue().start_at(start);
}

bool Trace::enabled() { return trace_enabled; }

void Trace::line(const std::string& text) {
  if (trace_enabled) {
    queue().post(text);
  }
}

void Trace::report(const std::string& text) { queue().post(text); }

void Trace::closing(const std::string& text) { queue().post_waiting(text); }

void Trace::closing_dropped() { queue().post_dropped_in_all(); }

void Trace::flush() { queue().flush(); }

}  // namespace rsaml
