/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The running architecture: its modules, their timed releases and their scheduling, the start and the stop.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "rsaml/clock.hpp"
#include "rsaml/measure.hpp"
#include "rsaml/module.hpp"
#include "rsaml/options.hpp"

namespace rsaml {

/**
 * Scheduling policy of a timed release: SCHED_FIFO or SCHED_RR at its rank, or (the releases of an
 * EDF processor) SCHED_DEADLINE where the kernel permits it, SCHED_FIFO at the rank otherwise.
 */
enum class Policy { Fifo, RoundRobin, Deadline };

/**
 * The running architecture: its modules, their timed releases, the start and the stop. Its members
 * are defined by concern: system.cpp (registration, the release loop, the run), scheduling.cpp (cores
 * and scheduling policies), measure.cpp (jobs measured, the summary), clock.cpp (sleeping, busy work).
 */
class System {
 public:
  explicit System(std::string name);
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  /** Registers a module; start steps run in registration order. */
  void add(Module& module);
  /**
   * Releases body every period from the run's epoch plus offset, on a thread of its own
   * with the given policy and rank (1 is the lowest real-time priority); each job is measured
   * against bounds.
   */
  void every(Module& module, std::string label, Nanos period, Nanos offset, Policy policy, int rank, JobBounds bounds,
             std::function<void()> body);
  /** Runs until options.run_for_ms have passed or the process is interrupted; returns the exit status. */
  int run(const Options& options);

  /**
   * Places a thread of a module: on its processor's core (its CPU here) when it has one; otherwise,
   * when some processor claims a core, on the cores none claims, so that no processor's core runs
   * work its analysis does not count. Says so in the trace, or why it could not.
   */
  void place(std::thread::native_handle_type thread, const std::string& label, const Module& module);
  /**
   * Gives the calling worker thread of a module priority 0 of the analysis, below every release:
   * SCHED_FIFO at the lowest real-time priority where permitted; or, for a module whose reactions are
   * aperiodic (unbounded), the default priority (SCHED_OTHER), below every real-time thread. Says which
   * in the trace.
   */
  std::string schedule_worker(const std::string& module, bool unbounded);
  /** The record of a module's measured reactions (see Module::measure_reactions). */
  Reactions& reactions(Module& module, std::string label, JobBounds bounds);
  /** Measures one reaction, as job_done does a release's job. */
  void reaction_done(Reactions& reactions, Clock::time_point arrived, Clock::time_point started, Clock::time_point done,
                     Nanos cpu, Nanos stall);
  /** CPU time the --busy-work option has a job of modeled cost consume. */
  Nanos busy_work(Nanos cost) const;
  /** Sleeps until t; false when the run is stopping. */
  bool sleep_until(Clock::time_point t);
  bool stopping() const { return stopping_.load(); }
  std::uint64_t new_wave() { return waves_.fetch_add(1) + 1; }

 private:
  struct Release {
    Module* module = nullptr;
    std::string label;
    Nanos period{0};
    Nanos offset{0};
    Policy policy = Policy::Fifo;
    int rank = 0;
    JobBounds bounds{};
    std::function<void()> body;
    std::thread thread;
    std::string sched;  // the scheduling it got, as the trace says it
    JobStats stats;
    // EDF: SCHED_DEADLINE asked for at the first release (become_deadline); where, said in the trace
    bool deadline_wanted = false;
    std::string unpinned;
    long tid = 0;                     // the thread's id, once a deadline thread
    std::atomic<bool> yielding{false};  // a deadline thread waiting in sched_yield() for its next period
  };
  void run_release(Release& release);
  /**
   * Gives the calling release thread its core and its scheduling; says which in the trace (for a release of an EDF
   * processor, at its first release: become_deadline).
   */
  void schedule_self(Release& release);
  /**
   * At the first release of a release of an EDF processor: puts the calling thread under SCHED_DEADLINE, so that the
   * kernel's first period begins at this release and its later periods are the release's next ones; says so in the
   * trace. False (the thread left at its real-time rank, on its core, and the trace saying why) when the kernel refuses.
   */
  bool become_deadline(Release& release, Clock::time_point release_at);
  /** At the stop: the deadline threads waiting for their next period (sched_yield) are let go at once. */
  void let_deadline_threads_go();
  /**
   * Measures one job: its response (release to completion) and execution (thread CPU) time; a deadline thread's job
   * also where it started and its context switches, listed with it where it is over its bound.
   */
  void job_done(Release& release, Clock::time_point released, Clock::time_point done, Nanos cpu, Nanos stall,
                const Clock::time_point* started = nullptr, long switches = 0);
  void print_summary();

  /**
   * Finds the cores the processors claim (their CPUs here) and the ones left for threads without a
   * core; says when the modules without a core of several hosts must share those.
   */
  void claim_cores();

  std::string name_;
  std::vector<Module*> modules_;
  std::vector<std::unique_ptr<Release>> releases_;
  std::vector<std::unique_ptr<Reactions>> reactions_;
  Options options_;
  Clock::time_point start_;  // of the run, as the trace counts it
  bool cores_claimed_ = false;
  std::vector<int> unclaimed_cores_;
  std::vector<int> all_cores_;
  std::size_t ready_ = 0;  // release threads placed and scheduled, under epoch_mutex_
  // The release threads wait for the epoch, set once every thread has its core and priority.
  std::mutex epoch_mutex_;
  std::condition_variable epoch_cv_;
  bool epoch_set_ = false;
  Clock::time_point epoch_;
  std::atomic<bool> stopping_{false};
  std::atomic<std::uint64_t> waves_{0};
};

}  // namespace rsaml
