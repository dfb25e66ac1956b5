/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The running architecture: its modules, their timed releases, the start and the stop.
#include "rsaml/system.hpp"

#include <algorithm>
#include <csignal>

#if defined(__linux__)
#include <sched.h>
#endif

#include "rsaml/internal.hpp"
#include "rsaml/jobs.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

using internal::thread_cpu_time;

namespace {

volatile std::sig_atomic_t interrupted = 0;

void on_signal(int) { interrupted = 1; }

// The room of the jobs a release (or reactions) may list, taken here, by the thread that makes the system and frees it:
// the thread that measures the jobs, real-time or not, never allocates it (docs/timing.md, "Memory between threads").
void reserve(JobStats& stats) {
  stats.listed.reserve(rsaml_jobs::LISTED);
  stats.details.reserve(rsaml_jobs::LISTED);
}

}  // namespace

System::System(std::string name) : name_(std::move(name)) {}

System::~System() {
  stopping_ = true;
  for (auto& release : releases_) {
    if (release->thread.joinable()) {
      release->thread.join();
    }
  }
}

void System::add(Module& module) { modules_.push_back(&module); }

void System::every(Module& module, std::string label, Nanos period, Nanos offset, Policy policy, int rank,
                   JobBounds bounds, std::function<void()> body) {
  std::unique_ptr<Release> release(new Release());
  release->module = &module;
  release->label = std::move(label);
  release->period = period;
  release->offset = offset;
  release->policy = policy;
  release->rank = rank;
  release->bounds = bounds;
  release->body = std::move(body);
  reserve(release->stats);
  releases_.push_back(std::move(release));
}

Reactions& System::reactions(Module& module, std::string label, JobBounds bounds) {
  reactions_.push_back(std::unique_ptr<Reactions>(new Reactions{&module, std::move(label), bounds, std::string(), JobStats()}));
  reserve(reactions_.back()->stats);
  return *reactions_.back();
}

void System::run_release(Release& release) {
  schedule_self(release);
  Clock::time_point next;
  {
    std::unique_lock<std::mutex> lock(epoch_mutex_);
    ++ready_;
    epoch_cv_.notify_all();
    epoch_cv_.wait(lock, [this] { return epoch_set_; });
    next = epoch_ + release.offset;
  }
  const Nanos busy = busy_work(release.bounds.cost);
  // EDF: a deadline thread from its first release on (become_deadline), whose grid then starts where the kernel's
  // first period does. It ends each job with sched_yield(), which gives up the rest of the period's runtime until the
  // kernel's next period, its next release: it resumes there with a fresh runtime, so the kernel's periods stay the
  // releases, and a thread that never sleeps meets none of the kernel's wake-up rules (docs/timing.md, "EDF").
  bool deadline = false;
  if (release.deadline_wanted) {
    if (!sleep_until(next)) {
      return;
    }
    const Clock::time_point asked = Clock::now();
    deadline = become_deadline(release, next);
    if (deadline) {
      next = asked;
    }
  }
  unsigned long overruns = internal::deadline_overruns();
  // Releases stay on the grid epoch + offset + k * period, however long one of them takes (a deadline thread's grid
  // from its first period); a job never starts before its release.
  while (sleep_until(next)) {
    const Clock::time_point started = Clock::now();
    const Nanos cpu = thread_cpu_time();
    const long switches = deadline ? internal::thread_switches() : 0;
    release.stats.worst_start_latency =
        std::max(release.stats.worst_start_latency, std::chrono::duration_cast<Nanos>(started - next));
    const Nanos stall = release.module->timed_release(release.label, next, release.body, busy);
    const Nanos used = thread_cpu_time() - cpu;
    if (deadline) {
      job_done(release, next, Clock::now(), used, stall, &started, internal::thread_switches() - switches);
    } else {
      job_done(release, next, Clock::now(), used, stall);
    }
    next += release.period;
    if (deadline) {
      const unsigned long now_overruns = internal::deadline_overruns();
      if (now_overruns != overruns) {
        Trace::report("throttled " + release.label + " job " + std::to_string(release.stats.jobs) + ": the kernel signalled " +
                      std::to_string(now_overruns - overruns) + " time(s) that its runtime ran out");
        overruns = now_overruns;
      }
      // the next period, unless the job ended past its next release (then the next job starts at once)
      if (Clock::now() < next) {
        release.yielding.store(true);
        if (!stopping_.load()) {
#if defined(__linux__)
          sched_yield();
#endif
        }
        release.yielding.store(false);
      }
    }
  }
}

int System::run(const Options& options) {
  const Clock::time_point start = Clock::now();
  start_ = start;
  options_ = options;
  Trace::configure(options.trace, start);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  Trace::line("run " + name_ +
              (options.run_for_ms >= 0 ? " for " + std::to_string(options.run_for_ms) + " ms" : std::string(" until interrupted")));
  // Every module sends its initial outputs before any reacts: the start is one wave.
  const std::uint64_t start_wave = new_wave();
  for (Module* module : modules_) {
    module->start_step(start_wave);
  }
  if (std::any_of(releases_.begin(), releases_.end(), [](const std::unique_ptr<Release>& r) { return r->policy == Policy::Deadline; })) {
    internal::count_deadline_overruns();  // before any thread starts: only the deadline threads take the signal
  }
  claim_cores();
  for (Module* module : modules_) {
    module->start_worker();
  }
  // Each release thread gets its core and its priority before its first job: they all wait for
  // the epoch, set once the last one is placed.
  for (auto& release : releases_) {
    Release* r = release.get();
    r->thread = std::thread([this, r] { run_release(*r); });
  }
  {
    std::unique_lock<std::mutex> lock(epoch_mutex_);
    epoch_cv_.wait(lock, [this] { return ready_ == releases_.size(); });
    // The first releases come a moment later, when every release thread is asleep waiting for them.
    epoch_ = Clock::now() + std::chrono::milliseconds(2);
    epoch_set_ = true;
  }
  epoch_cv_.notify_all();
  const Clock::time_point deadline =
      options.run_for_ms >= 0 ? start + std::chrono::milliseconds(options.run_for_ms) : Clock::time_point::max();
  while (!interrupted) {
    const Clock::time_point now = Clock::now();
    if (now >= deadline) {
      break;
    }
    std::this_thread::sleep_until(std::min(deadline, now + std::chrono::milliseconds(20)));
  }
  stopping_ = true;
  let_deadline_threads_go();
  for (auto& release : releases_) {
    if (release->thread.joinable()) {
      release->thread.join();
    }
  }
  for (Module* module : modules_) {
    module->stop_worker();
  }
  const long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count();
  print_summary();
  Trace::line("stop after " + std::to_string(ms) + " ms");
  Trace::flush();
  return 0;
}

}  // namespace rsaml
