/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Time on the run's clock and on the thread's: sleeping to a release, CPU time, busy work.
#include <algorithm>
#include <ctime>
#include <thread>

#if defined(__linux__)
#include <sys/resource.h>
#endif

#include "rsaml/internal.hpp"
#include "rsaml/jobs.hpp"
#include "rsaml/system.hpp"

namespace rsaml {

/** The calling thread's CPU time. */
Nanos internal::thread_cpu_time() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec t{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0) {
    return Nanos(static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec);
  }
#endif
  return std::chrono::duration_cast<Nanos>(Clock::now().time_since_epoch());
}

long internal::thread_switches() {
#if defined(__linux__)
  rusage usage{};
  if (getrusage(RUSAGE_THREAD, &usage) == 0) {
    return usage.ru_nvcsw + usage.ru_nivcsw;
  }
#endif
  return 0;
}

Nanos internal::stall_since(Clock::time_point locked, Nanos cpu, Nanos waited) {
  const Nanos used = thread_cpu_time() - cpu;
  const Nanos wall = std::chrono::duration_cast<Nanos>(Clock::now() - locked);
  return std::max(Nanos(0), wall - used - waited);
}

/** Consumes CPU time on the calling thread: busy work standing in for user code. */
void internal::consume(Nanos amount) {
  const Nanos until = thread_cpu_time() + amount;
  while (thread_cpu_time() < until) {
  }
}

bool System::sleep_until(Clock::time_point t) {
  // No lock shared with other threads: a real-time thread must not wait for one that holds it
  // while preempted. The stop is seen within a slice.
  constexpr Nanos kSlice = std::chrono::milliseconds(20);
  for (;;) {
    if (stopping_.load()) {
      return false;
    }
    const Clock::time_point now = Clock::now();
    if (now >= t) {
      return true;
    }
    const Clock::time_point until = t - now > kSlice ? now + kSlice : t;
#if defined(__linux__)
    // steady_clock is CLOCK_MONOTONIC: sleep to the absolute time, with no drift.
    const long long ns = std::chrono::duration_cast<Nanos>(until.time_since_epoch()).count();
    timespec at{};
    at.tv_sec = static_cast<time_t>(ns / 1000000000LL);
    at.tv_nsec = static_cast<long>(ns % 1000000000LL);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &at, nullptr);
#else
    std::this_thread::sleep_until(until);
#endif
  }
}

Nanos System::busy_work(Nanos cost) const {
  // The rule the ROS 2 nodes share: short of the modeled time by 5 % (at most 100 us).
  return Nanos(rsaml_jobs::busy_work_ns(cost.count(), options_.busy_work_percent / 100.0));
}

}  // namespace rsaml
