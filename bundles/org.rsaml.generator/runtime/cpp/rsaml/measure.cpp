/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Each job measured against its bounds, misses and overruns said as they happen, and the summary of the run.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rsaml/internal.hpp"
#include "rsaml/jobs.hpp"
#include "rsaml/module.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

using internal::millis;

namespace {

// Counts one job (of a timed release or a reaction) that started its response at `from`: its
// response, execution time and stall, and a miss or an overrun as it happens.
// A deadline thread's job (`detail`: where it started, its CPU time and context switches) is listed with them.
void record_job(JobStats& s, const std::string& label, const JobBounds& bounds, Clock::time_point from,
                Clock::time_point done, Nanos cpu, Nanos stall, const std::array<std::int64_t, 3>* detail = nullptr) {
  if (s.jobs++ == 0) {
    s.first_release = from;  // listed's and details' room taken when the release was made (System::every, System::reactions)
  }
  s.last_release = from;
  const Nanos response = std::chrono::duration_cast<Nanos>(done - from);
  s.worst_response = std::max(s.worst_response, response);
  s.worst_execution = std::max(s.worst_execution, cpu);
  s.worst_stall = std::max(s.worst_stall, stall);
  // the steady clock is CLOCK_MONOTONIC (libstdc++ and libc++ on Linux), the platform monitor's clock
  const std::size_t listed = s.listed.size();
  const std::array<std::int64_t, 2> last = listed > 0 ? s.listed.back() : std::array<std::int64_t, 2>{0, 0};
  rsaml_jobs::record_instant(std::chrono::duration_cast<Nanos>(from.time_since_epoch()).count(),
                             std::chrono::duration_cast<Nanos>(done.time_since_epoch()).count(), bounds.response.count(), s.worst_job,
                             s.over_bound, s.listed);
  if (detail != nullptr && s.listed.size() > listed) {
    s.details.push_back(*detail);  // listed: appended, or (the worst of the rest) put in the last place
  } else if (detail != nullptr && listed > 0 && s.listed.back() != last && !s.details.empty()) {
    s.details.back() = *detail;
  }
  if (bounds.deadline.count() > 0 && response > bounds.deadline) {
    ++s.misses;
    Trace::report("miss " + label + " job " + std::to_string(s.jobs) + " response " + millis(response) + " > deadline " +
                  millis(bounds.deadline));
  }
  if (bounds.cost.count() > 0 && cpu > bounds.cost) {
    ++s.overruns;
    Trace::report("overrun " + label + " job " + std::to_string(s.jobs) + " execution " + millis(cpu) + " > modeled " +
                  millis(bounds.cost));
  }
}

}  // namespace

void System::reaction_done(Reactions& r, Clock::time_point arrived, Clock::time_point started, Clock::time_point done,
                           Nanos cpu, Nanos stall) {
  r.stats.worst_start_latency = std::max(r.stats.worst_start_latency, std::chrono::duration_cast<Nanos>(started - arrived));
  record_job(r.stats, r.label, r.bounds, arrived, done, cpu, stall);
}

void System::job_done(Release& r, Clock::time_point released, Clock::time_point done, Nanos cpu, Nanos stall,
                      const Clock::time_point* started, long switches) {
  if (started == nullptr) {
    record_job(r.stats, r.label, r.bounds, released, done, cpu, stall);
    return;
  }
  const std::array<std::int64_t, 3> detail{std::chrono::duration_cast<Nanos>(started->time_since_epoch()).count(), cpu.count(),
                                           static_cast<std::int64_t>(switches)};
  record_job(r.stats, r.label, r.bounds, released, done, cpu, stall, &detail);
}

namespace {

// The summary line of one release's (or module's reactions') jobs, through the writer the ROS 2 nodes share; the run's
// closing lines, which wait for room in the trace's queue rather than be dropped.
void summary(Clock::time_point start, const std::string& label, const JobStats& s, const JobBounds& b, const std::string& sched) {
  rsaml_jobs::Observed o;
  o.label = label;
  o.jobs = s.jobs;
  o.first_release_ns = std::chrono::duration_cast<Nanos>(s.first_release - start).count();
  o.last_release_ns = std::chrono::duration_cast<Nanos>(s.last_release - start).count();
  o.misses = s.misses;
  o.overruns = s.overruns;
  o.worst_response_ns = s.worst_response.count();
  o.bound_ns = b.response.count();
  o.deadline_ns = b.deadline.count();
  o.worst_execution_ns = s.worst_execution.count();
  o.modeled_ns = b.cost.count();
  o.worst_start_latency_ns = s.worst_start_latency.count();
  o.worst_stall_ns = s.worst_stall.count();
  o.sched = sched;
  o.worst_job = s.worst_job;
  o.over_bound = s.over_bound;
  o.listed = s.listed;
  const std::vector<std::string> lines = rsaml_jobs::over_bound_lines(o);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    // a deadline thread's job also says where it started, its CPU time and its context switches (docs/timing.md)
    Trace::closing(s.details.size() != lines.size() ? lines[i]
                                                    : lines[i] + " started " + std::to_string(s.details[i][0]) + " ns cpu " +
                                                          std::to_string(s.details[i][1]) + " ns switches " + std::to_string(s.details[i][2]));
  }
  Trace::closing(rsaml_jobs::line(o));
}

}  // namespace

void System::print_summary() {
  for (auto& release : releases_) {
    summary(start_, release->label, release->stats, release->bounds, release->sched);
  }
  for (auto& reactions : reactions_) {
    summary(start_, reactions->label, reactions->stats, reactions->bounds, reactions->sched);
  }
  for (Module* module : modules_) {
    const std::uint64_t dropped = module->mail_dropped();
    if (dropped > 0) {
      Trace::closing(internal::mailbox_dropped(module->name(), dropped, dropped, true));
    }
  }
  Trace::closing_dropped();
}

}  // namespace rsaml
