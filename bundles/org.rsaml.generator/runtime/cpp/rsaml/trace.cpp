/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The run's trace on standard output, and durations as it says them.
#include "rsaml/trace.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

#include "rsaml/internal.hpp"

namespace rsaml {

namespace {

std::mutex trace_mutex;
std::atomic<bool> trace_enabled{true};
Clock::time_point trace_start = Clock::now();

}  // namespace

std::string internal::millis(Nanos t) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ms", static_cast<double>(t.count()) / 1e6);
  return text;
}

void Trace::configure(bool enabled, Clock::time_point start) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  trace_enabled = enabled;
  trace_start = start;
}

bool Trace::enabled() { return trace_enabled; }

void Trace::line(const std::string& text) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  if (!trace_enabled) {
    return;
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - trace_start).count();
  std::fprintf(stdout, "[%10.3f ms] %s\n", ms, text.c_str());
}

void Trace::report(const std::string& text) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - trace_start).count();
  std::fprintf(stdout, "[%10.3f ms] %s\n", ms, text.c_str());
}

void Trace::flush() {
  std::lock_guard<std::mutex> lock(trace_mutex);
  std::fflush(stdout);
}

}  // namespace rsaml
