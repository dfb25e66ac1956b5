/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// What each job of a timed release or a reaction is measured against, and what was measured.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rsaml/clock.hpp"

namespace rsaml {

/**
 * What the model and the timing analysis say of each job of a timed release or a reaction; the
 * runtime measures every job against it.
 */
struct JobBounds {
  Nanos deadline;  // relative deadline: the modeled delay, or the period (minimum interval); 0: none
  Nanos cost;      // modeled execution time; 0 when the model gives none
  Nanos response;  // the analysis's worst-case response time; negative when it gives none
};

/** What a release thread (or a module's worker, of its reactions) observed of its jobs. */
struct JobStats {
  std::uint64_t jobs = 0;
  std::uint64_t misses = 0;
  std::uint64_t overruns = 0;
  Nanos worst_response{0};
  Nanos worst_execution{0};
  Nanos worst_start_latency{0};
  Nanos worst_stall{0};  // ready but not running during a job: its wall time (module's lock held) minus its CPU time
  Clock::time_point first_release{};  // of the first job; the summary gives it and the last since the run's start
  Clock::time_point last_release{};
  // On CLOCK_MONOTONIC (the steady clock's own on Linux): the worst job, and the jobs over the plain bound (rsaml/jobs.hpp, record_instant).
  std::array<std::int64_t, 2> worst_job{0, 0};
  std::uint64_t over_bound = 0;
  std::vector<std::array<std::int64_t, 2>> listed;
  // A deadline thread's (EDF): for each listed job, where it started (CLOCK_MONOTONIC), its CPU time and its context switches (ns, ns, count)
  std::vector<std::array<std::int64_t, 3>> details;
};

}  // namespace rsaml
