/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Each job measured against its bounds, misses and overruns said as they happen, and the summary of the run.
#include <algorithm>
#include <cstdio>
#include <string>

#include "rsaml/internal.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

using internal::millis;

namespace {

// Counts one job (of a timed release or a reaction) that started its response at `from`: its
// response and execution time, and a miss or an overrun as it happens.
void record_job(JobStats& s, const std::string& label, const JobBounds& bounds, Clock::time_point from,
                Clock::time_point done, Nanos cpu) {
  if (s.jobs++ == 0) {
    s.first_release = from;
  }
  s.last_release = from;
  const Nanos response = std::chrono::duration_cast<Nanos>(done - from);
  s.worst_response = std::max(s.worst_response, response);
  s.worst_execution = std::max(s.worst_execution, cpu);
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
                           Nanos cpu) {
  r.stats.worst_start_latency = std::max(r.stats.worst_start_latency, std::chrono::duration_cast<Nanos>(started - arrived));
  record_job(r.stats, r.label, r.bounds, arrived, done, cpu);
}

void System::job_done(Release& r, Clock::time_point released, Clock::time_point done, Nanos cpu) {
  record_job(r.stats, r.label, r.bounds, released, done, cpu);
}

namespace {
std::string since(Clock::time_point start, Clock::time_point t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", std::chrono::duration<double, std::milli>(t - start).count());
  return text;
}

// One format for the C++ runtime and the ROS 2 nodes (docs/timing.md): the same keys in the same order.
void summary(Clock::time_point start, const std::string& label, const JobStats& s, const JobBounds& b, const std::string& sched) {
  Trace::report("summary " + label + " jobs " + std::to_string(s.jobs) + " released " +
                (s.jobs > 0 ? since(start, s.first_release) + ".." + since(start, s.last_release) + " ms" : std::string("none")) +
                " misses " + std::to_string(s.misses) + " overruns " +
                std::to_string(s.overruns) + " worst-response " + millis(s.worst_response) + " bound " +
                (b.response.count() >= 0 ? millis(b.response) : std::string("none")) + " deadline " +
                (b.deadline.count() > 0 ? millis(b.deadline) : std::string("none")) + " worst-execution " +
                millis(s.worst_execution) + " modeled " + millis(b.cost) + " worst-start-latency " +
                millis(s.worst_start_latency) + " sched " + sched);
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
