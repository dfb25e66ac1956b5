/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// What the C++ runtime and the ROS 2 nodes share about jobs, written here once: the busy work that
// stands in for user code, and the summary line of a timed release's or a reaction's jobs
// (docs/timing.md, "What the C++ program measures"). Internal linkage, so that two generated
// libraries in one process (ROS 2 components) never mix their copies.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace rsaml_jobs {
namespace {

/** Now on CLOCK_MONOTONIC, in ns: the clock the tests' platform monitor records on, so that a job can be placed on its records. */
inline std::int64_t monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

/** A job on CLOCK_MONOTONIC, in ns: its release and its completion. */
using Instant = std::array<std::int64_t, 2>;

/**
 * How many of a release's jobs over its plain bound are listed: the first LISTED - 1, then the worst of the rest
 * (16 KiB a release, taken at its first job; the lines are printed at exit).
 */
constexpr std::size_t LISTED = 1024;

/**
 * Records where on CLOCK_MONOTONIC a job ran, for a check of the bound that places each job on the
 * platform's timeline (docs/timing.md, "The platform's allowance"): the worst job so far (`worst`),
 * and each job whose response exceeds the analysis's plain bound `bound_ns` (negative: none; a job
 * within it needs no allowance), counted in `over_bound` and listed in `listed`, the first LISTED - 1
 * of them and, in the last place, the worst of the rest, so that the worst is always listed. The
 * caller holds its statistics' lock, and reserves `listed`'s room (LISTED) before its first job
 * (the C++ runtime when it makes the release, on the thread that frees it). Plain
 * types only, so that each runtime keeps them in its own statistics.
 */
inline void record_instant(std::int64_t release_ns, std::int64_t done_ns, std::int64_t bound_ns, Instant& worst, std::uint64_t& over_bound,
                           std::vector<Instant>& listed) {
  const std::int64_t response = done_ns - release_ns;
  if (worst[1] == 0 || response > worst[1] - worst[0]) {
    worst = Instant{release_ns, done_ns};
  }
  if (bound_ns < 0 || response <= bound_ns) {
    return;
  }
  ++over_bound;
  if (listed.size() < LISTED) {
    listed.push_back(Instant{release_ns, done_ns});
  } else if (response > listed.back()[1] - listed.back()[0]) {
    listed.back() = Instant{release_ns, done_ns};
  }
}

/** What the model and the analysis say of a release's (or a module's reactions') jobs, and what was observed; times in ns. */
struct Observed {
  std::string label;
  std::uint64_t jobs = 0;
  std::int64_t first_release_ns = 0;  // since the run's start; unused without a job
  std::int64_t last_release_ns = 0;
  std::uint64_t misses = 0;
  std::uint64_t overruns = 0;
  std::int64_t worst_response_ns = 0;
  std::int64_t bound_ns = -1;    // the analysis's worst-case response; negative: none
  std::int64_t deadline_ns = 0;  // 0: none
  std::int64_t worst_execution_ns = 0;
  std::int64_t modeled_ns = 0;
  std::int64_t worst_start_latency_ns = 0;
  std::int64_t worst_stall_ns = 0;
  std::string sched;
  Instant worst_job{0, 0};  // on CLOCK_MONOTONIC; {0, 0} without a job
  std::uint64_t over_bound = 0;
  std::vector<Instant> listed;
};

/**
 * The busy work of a job of modeled cost `cost_ns` at `fraction` of it (--busy-work PERCENT / 100 on
 * the C++ runtime, rsaml.simulated_load on ROS 2): that share of the cost, short of it by 5 % of the
 * cost (at most 0.1 ms), which the job's own bookkeeping (the lock, the trace, the sends or the
 * publishing) takes instead, so that a job running as modeled is not reported as an overrun. 0 for
 * no busy work.
 */
inline std::int64_t busy_work_ns(std::int64_t cost_ns, double fraction) {
  if (!(fraction > 0.0) || cost_ns <= 0) {
    return 0;
  }
  const std::int64_t share = static_cast<std::int64_t>(static_cast<double>(cost_ns) * fraction);
  const std::int64_t bookkeeping = cost_ns / 20 < 100000 ? cost_ns / 20 : 100000;
  return share > bookkeeping ? share - bookkeeping : 0;
}

/** Milliseconds with three decimals: 1.250. */
inline std::string ms(std::int64_t ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", static_cast<double>(ns) / 1e6);
  return text;
}

/** The line, without the trace's time stamp: `summary <label> jobs ... sched <sched>` (sched last: it is free text). */
inline std::string line(const Observed& o) {
  return "summary " + o.label + " jobs " + std::to_string(o.jobs) + " released " +
         (o.jobs > 0 ? ms(o.first_release_ns) + ".." + ms(o.last_release_ns) + " ms" : std::string("none")) + " misses " +
         std::to_string(o.misses) + " overruns " + std::to_string(o.overruns) + " worst-response " + ms(o.worst_response_ns) +
         " ms bound " + (o.bound_ns >= 0 ? ms(o.bound_ns) + " ms" : std::string("none")) + " deadline " +
         (o.deadline_ns > 0 ? ms(o.deadline_ns) + " ms" : std::string("none")) + " worst-execution " + ms(o.worst_execution_ns) +
         " ms modeled " + ms(o.modeled_ns) + " ms worst-start-latency " + ms(o.worst_start_latency_ns) + " ms worst-stall " +
         ms(o.worst_stall_ns) + " ms worst-job " +
         (o.worst_job[1] != 0 ? std::to_string(o.worst_job[0]) + ".." + std::to_string(o.worst_job[1]) + " ns" : std::string("none")) +
         " over-bound " + std::to_string(o.over_bound) + " listed " + std::to_string(o.listed.size()) + " sched " +
         (o.sched.empty() ? std::string("default") : o.sched);
}

/**
 * The lines that list the jobs over the plain bound, one each, printed with the summary line:
 * `over-bound <label> job <release>..<done> ns` on CLOCK_MONOTONIC.
 */
inline std::vector<std::string> over_bound_lines(const Observed& o) {
  std::vector<std::string> lines;
  for (const Instant& j : o.listed) {
    lines.push_back("over-bound " + o.label + " job " + std::to_string(j[0]) + ".." + std::to_string(j[1]) + " ns");
  }
  return lines;
}

}  // namespace
}  // namespace rsaml_jobs
