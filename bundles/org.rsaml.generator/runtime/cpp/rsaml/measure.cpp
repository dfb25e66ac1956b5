/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Each job measured against its bounds, misses and overruns said as they happen, and the summary of the run.
#include <algorithm>
#include <string>

#include "rsaml/internal.hpp"
#include "rsaml/jobs.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

using internal::millis;

namespace {

// Counts one job (of a timed release or a reaction) that started its response at `from`: its
// response, execution time and stall, and a miss or an overrun as it happens.
void record_job(JobStats& s, const std::string& label, const JobBounds& bounds, Clock::time_point from,
                Clock::time_point done, Nanos cpu, Nanos stall) {
  if (s.jobs++ == 0) {
    s.first_release = from;
    s.listed.reserve(rsaml_jobs::LISTED);
  }
  s.last_release = from;
  const Nanos response = std::chrono::duration_cast<Nanos>(done - from);
  s.worst_response = std::max(s.worst_response, response);
  s.worst_execution = std::max(s.worst_execution, cpu);
  s.worst_stall = std::max(s.worst_stall, stall);
  // the steady clock is CLOCK_MONOTONIC (libstdc++ and libc++ on Linux), the platform monitor's clock
  rsaml_jobs::record_instant(std::chrono::duration_cast<Nanos>(from.time_since_epoch()).count(),
                             std::chrono::duration_cast<Nanos>(done.time_since_epoch()).count(), bounds.response.count(), s.worst_job,
                             s.over_bound, s.listed);
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

void System::job_done(Release& r, Clock::time_point released, Clock::time_point done, Nanos cpu, Nanos stall) {
  record_job(r.stats, r.label, r.bounds, released, done, cpu, stall);
}

namespace {

// The summary line of one release's (or module's reactions') jobs, through the writer the ROS 2 nodes share.
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
  for (const std::string& line : rsaml_jobs::over_bound_lines(o)) {
    Trace::report(line);
  }
  Trace::report(rsaml_jobs::line(o));
}

}  // namespace

void System::print_summary() {
  for (auto& release : releases_) {
    summary(start_, release->label, release->stats, release->bounds, release->sched);
  }
  for (auto& reactions : reactions_) {
    summary(start_, reactions->label, reactions->stats, reactions->bounds, reactions->sched);
  }
}

}  // namespace rsaml
