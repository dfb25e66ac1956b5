/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Scheduling of the nodes of an RsaML architecture as its timing analysis assumes (docs/timing.md):
// each timed release in a callback group of its own, served by an executor thread of its own at the
// release's real-time priority (SCHED_FIFO or SCHED_RR, the analysis's rank) on the processor's core;
// a node's data arrivals (reactions, input handlers, link triggers) in a callback group of their own,
// served the same way at priority 0 of the analysis (the lowest real-time priority, as the C++
// runtime's module worker); ROS 2's own services on the process's main executor at the default
// priority. Every job is measured (release, or the arrival that starts a reaction, to completion) and
// reported.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <rclcpp/rclcpp.hpp>
#include <rclcpp/version.h>

#include "rsaml/realtime.hpp"
#include "rsaml/usage.hpp"

namespace rsaml_ros2 {

/**
 * Queues one trace line, "[   12.345 ms] text", ms since the trace queue was made (the program's start), for the trace writer of the runtime package, a
 * thread of the default priority that writes it out at once (rsaml/tracequeue.hpp): the caller never waits for
 * standard output, a slow or full pipe stalls only the writer. A line that finds the queue full is dropped and the
 * writer says how many ("trace dropped N lines ..."), as does each node's summary ("... in all").
 */
void trace(const std::string& text);

/**
 * The option of a process's command line (before --ros-args) that sets how long spin() serves its
 * managed nodes after SIGINT or SIGTERM, in milliseconds: `--rsaml-shutdown-grace-ms=5000`. The
 * generated launch files give it to every process with managed nodes, from the number of nodes its
 * lifecycle manager brings down (each within its own deadline; see the README, "Nodes are plain
 * rclcpp nodes unless"); without it, GRACE_WITHOUT_ARGUMENT_MS, as for one managed node.
 */
constexpr const char* GRACE_OPTION = "--rsaml-shutdown-grace-ms";
constexpr long long GRACE_WITHOUT_ARGUMENT_MS = 3000;

/**
 * rclcpp::init without rclcpp's signal handlers: SIGINT and SIGTERM ask spin() below to stop, so that
 * the process can still serve its managed nodes' transitions while the lifecycle manager (which gets
 * the same signal from ros2 launch, or from the terminal) deactivates and cleans them up. Takes
 * GRACE_OPTION from the command line; throws UsageError when its value is not a number (rsaml/usage.hpp).
 */
void init(int argc, char** argv);

/**
 * Spins the process's main executor until SIGINT or SIGTERM (see init()); then, while a managed node
 * of the process is still configured (inactive or active), goes on serving it for at most the grace
 * init() took, a second signal ending the wait; a node still configured then is said in the trace. A
 * process of plain nodes stops at once.
 */
void spin(rclcpp::Executor& executor);

/**
 * What the model and the timing analysis say of the jobs of a timed release or of a node's
 * reactions, and what was observed of them (the C++ runtime's JobBounds and JobStats in one).
 */
struct Jobs {
  std::string label;
  std::int64_t deadline_ns = 0;
  std::int64_t cost_ns = 0;
  std::int64_t bound_ns = -1;  // the timing analysis's worst-case response; negative: none
  std::string sched;           // the scheduling its thread got, as traced
  std::uint64_t jobs = 0;
  std::uint64_t misses = 0;
  std::uint64_t overruns = 0;
  std::int64_t worst_response_ns = 0;
  std::int64_t worst_execution_ns = 0;
  std::int64_t worst_latency_ns = 0;
  std::int64_t worst_stall_ns = 0;  // ready but not running during a job (node's lock held): wall time minus CPU time
  std::int64_t first_release_ns = -1;
  std::int64_t last_release_ns = -1;
  // On CLOCK_MONOTONIC: the worst job, and the jobs over the plain bound (rsaml/jobs.hpp, record_instant).
  std::array<std::int64_t, 2> worst_job{0, 0};
  std::uint64_t over_bound = 0;
  std::vector<std::array<std::int64_t, 2>> listed;
};

/** A timed release of a node: its jobs and how its thread is scheduled. */
struct Release : Jobs {
  int rank = 1;
  bool round_robin = false;
  bool edf = false;  // a release of an EDF processor: SCHED_DEADLINE where the kernel permits it
  std::atomic<long> deadline_tid{0};  // its thread's id while it runs as a deadline thread (rsaml_run_deadline), else 0
  std::atomic<bool> yielding{false};  // a deadline thread waiting in sched_yield() for its next period
  std::string unpinned;          // an EDF release's thread given every CPU of its process: said in its sched line
  int cpu = -1;                  // the CPU its thread is pinned to (place), -1 where none
  bool realtime = true;  // false: the data thread of aperiodic reactions, at the default priority
  std::int64_t period_ns = 0;
  rclcpp::CallbackGroup::SharedPtr group;
  // The executor's own work for a job: its thread's CPU time from the end of one job to the start of the next.
  std::int64_t job_end_cpu_ns = -1;  // -1 before the first job
  std::uint64_t executor_jobs = 0;
  std::int64_t executor_worst_ns = 0;
  std::int64_t executor_total_ns = 0;
};

/** Messages received at one entry port. */
struct Arrivals {
  std::string port;
  std::uint64_t messages = 0;
  std::int64_t first_ns = -1;
  std::int64_t last_ns = -1;
};

/**
 * What every generated node has, plain or managed: its releases, the lock its activations hold (the
 * module's lock of the analysis: a release and a reaction of one node never run at once) and the
 * measurements it prints at exit. It works through the node's interfaces, which rclcpp::Node and
 * rclcpp_lifecycle::LifecycleNode both offer.
 */
class Schedule {
 public:
  /** The schedule of `node` (an rclcpp::Node or rclcpp_lifecycle::LifecycleNode), which declares rsaml.simulated_load. */
  template <typename NodeT>
  Schedule(NodeT& node, std::string module, int core)
      : Schedule(node.get_node_base_interface(), node.get_node_timers_interface(), node.get_clock(),
                 node.template declare_parameter<double>("rsaml.simulated_load", 0.0), std::move(module), core) {}
  virtual ~Schedule();
  Schedule(const Schedule&) = delete;
  Schedule& operator=(const Schedule&) = delete;

  /** The schedule of a node base interface, when it is a generated node of this package; else null. */
  static Schedule* rsaml_of(const rclcpp::node_interfaces::NodeBaseInterface* base);
  /** The managed nodes of this process that are configured (inactive or active), as "module state". */
  static std::vector<std::string> rsaml_configured();

  /** The state of a managed node when it is configured ("inactive" or "active"); else (and for a plain node) null. */
  virtual const char* rsaml_configured_state() const { return nullptr; }

  /** The CPU core of the node's processor, or -1. */
  int rsaml_core() const { return core_; }
  std::deque<Release>& rsaml_releases() { return releases_; }
  /** The node's data arrivals as the executor thread that serves them sees them (rank 0), or null when it has none. */
  Release* rsaml_data() { return data_.get(); }
  const rclcpp::node_interfaces::NodeBaseInterface::SharedPtr& rsaml_base() const { return base_; }
  /**
   * Stops the node's EDF release loops (rsaml_run_deadline), before its executor threads are stopped: a loop starts
   * no job after it, and a deadline thread waiting for its next period is let go at once (made a normal thread), so
   * that the process stops without waiting a period.
   */
  void rsaml_stop_releases();

 protected:
  /**
   * A release at `rank` (or, edf, under SCHED_DEADLINE): its callback group, which only its own
   * executor thread serves; bound_ns is the timing analysis's bound on its response (negative: none).
   */
  std::size_t rsaml_add_release(const std::string& label, int rank, bool round_robin, std::int64_t deadline_ns, std::int64_t cost_ns,
                                std::int64_t period_ns = 0, std::int64_t bound_ns = -1, bool edf = false);
  /**
   * The timer of a release, on the node's clock, in the release's group: each job runs `body`
   * through rsaml_run_job(), released at the timer's expected call time (ROS 2 Jazzy and later; before,
   * at the time the callback starts, and the release latency is not measured). A job is released every
   * period: a release ROS 2's timer drops when it calls a period or more late is counted as a job that
   * missed its deadline (rsaml_count_dropped). The timers of a node start with the node (restarting each when its thread had its
   * scheduling went with bound checks failing on ROS 2; see docs/timing.md).
   */
  template <typename BodyT>
  rclcpp::TimerBase::SharedPtr rsaml_add_timer(std::size_t release, std::int64_t period_ns, BodyT body) {
#if RCLCPP_VERSION_GTE(28, 0, 0)
    // The timer itself, for its first call on an EDF release's thread (rsaml_run_deadline runs the release from there).
    auto self = std::make_shared<TimerOf>();
    auto timer = rclcpp::create_timer(
        base_, timers_, clock_, rclcpp::Duration::from_nanoseconds(period_ns),
        [this, release, period_ns, body, self](const rclcpp::TimerInfo& info) {
          rclcpp::TimerBase::SharedPtr me;
          if (releases_[release].edf && self->first(me) && this->rsaml_run_deadline(release, *me, info.expected_call_time, body)) {
            return;  // the release ran as a deadline thread until its timer was cancelled or the node stopped
          }
          this->rsaml_run_job(release, info.expected_call_time, info.actual_call_time, body);
          this->rsaml_count_dropped(release, period_ns, info.expected_call_time, info.actual_call_time);
        },
        releases_[release].group);
    self->set(timer);
    return timer;
#else
    return rclcpp::create_timer(
        base_, timers_, clock_, rclcpp::Duration::from_nanoseconds(period_ns),
        [this, release, body]() {
          const rclcpp::Time now = clock_->now();
          this->rsaml_run_job(release, now, now, body);
        },
        releases_[release].group);
#endif
  }
  /**
   * The releases ROS 2's timer dropped in a call at `called` of its release `expected`: a timer that
   * calls a period or more late moves its next call past `called` (rcl_timer_call), so the releases
   * due in between, expected + k * period before `called`, never run. Each is counted as a job of its
   * own that missed its deadline, and traced (`miss <label> released ... ms not run (N releases) ...`), so the release's
   * jobs stay on its grid and none is lost silently. (They are not run late: after a long stall, a
   * backlog run back to back at real-time priority would hold the CPU for as long again.)
   */
  void rsaml_count_dropped(std::size_t release, std::int64_t period_ns, const rclcpp::Time& expected, const rclcpp::Time& called);
  /**
   * An EDF release, from its timer's first call (`called`, its expected call time), on the release's own executor
   * thread: asks for SCHED_DEADLINE (runtime = the modeled cost, the modeled deadline and period, reclaiming
   * unreserved bandwidth), whose first period begins there, and then runs the release's jobs in a loop, as the C++
   * runtime's release thread does: each job ends with sched_yield(), which gives up the rest of its runtime until the
   * kernel's next period, its next release; a job that ends past its next release starts the next one at once. The
   * thread never goes back to wait for its timer, so it never sleeps between jobs and no wake-up rule of the kernel
   * (for deadlines shorter than periods, the runtime it would shorten) applies. Its jobs are released on the
   * kernel's grid from the request (its sched line says how long after `called` it asked). The loop ends when the timer is cancelled (a
   * managed node deactivated: a job in progress finishes, none starts) or the node's releases stop
   * (rsaml_stop_releases); the thread then leaves SCHED_DEADLINE for its rank, and a managed node activated again
   * asks anew at its new timer's first call. Where the kernel refuses, the thread stays at the release's rank, its
   * sched line says `instead of EDF` and why, and its timer releases its jobs (false).
   */
  bool rsaml_run_deadline(std::size_t release, rclcpp::TimerBase& timer, const rclcpp::Time& called, const std::function<void()>& body);
  /** A timer as its own callback sees it: set once created, taken on its first call only. */
  class TimerOf {
   public:
    void set(const rclcpp::TimerBase::SharedPtr& timer) {
      std::lock_guard<std::mutex> lock(mutex_);
      timer_ = timer;
    }
    /**
     * True on the first call that finds the timer set (with it in `timer`), false before and after: a call that
     * comes before its maker has set it (the maker preempted for a period) leaves the first call to the next one.
     */
    bool first(rclcpp::TimerBase::SharedPtr& timer) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (called_) {
        return false;
      }
      timer = timer_.lock();
      called_ = timer != nullptr;
      return called_;
    }

   private:
    std::mutex mutex_;
    std::weak_ptr<rclcpp::TimerBase> timer_;
    bool called_ = false;
  };
  std::size_t rsaml_add_arrivals(const std::string& port);
  /**
   * The callback group of every subscription of the node (entry ports, link triggers): served by an
   * executor thread of its own at priority 0 of the analysis, SCHED_FIFO's lowest priority, below
   * every release, pinned to the node's core (`sched <module> worker ...`, as the C++ runtime's
   * module worker). Created on the first call, which a node with subscriptions makes in its
   * constructor, so that the thread exists whenever the subscriptions are created.
   */
  rclcpp::CallbackGroup::SharedPtr rsaml_data_group();
  /**
   * Serves the node's data at the default priority (SCHED_OTHER), below every real-time thread, pinned
   * to the node's core all the same (`sched <module> worker default: it serves aperiodic reactions ...`):
   * a node whose reactions are aperiodic calls it in its constructor. The model bounds neither their
   * arrivals nor their load, and the analysis excludes them; at a real-time priority, a node sent more
   * than it can react to would take the real-time time of its CPUs, which Linux's real-time throttling
   * (sched_rt_runtime_us) then takes back from every real-time thread, the releases the analysis proved
   * included (docs/timing.md, "ROS 2").
   */
  void rsaml_data_unbounded();

  /**
   * Runs one job of a release under the node's lock and measures it: `released` is its release
   * time, `called` when the executor called it (the difference is the platform's release latency,
   * with any preemption by higher priorities before the call).
   */
  void rsaml_run_job(std::size_t release, const rclcpp::Time& released, const rclcpp::Time& called,
                     const std::function<void()>& body);
  /**
   * Runs what an arrival at an entry port does (its handler, and the reaction it may start) under
   * the node's lock; the arrival is when the executor hands the message over.
   */
  void rsaml_run_arrival(std::size_t port, const std::function<void()>& body);
  /**
   * Measures the node's reactions (a node that reacts to data calls it once, in its constructor),
   * against the modeled deadline and cost and the analysis's bound (negative: none).
   */
  void rsaml_measure_reactions(const std::string& label, std::int64_t deadline_ns, std::int64_t cost_ns, std::int64_t bound_ns);
  /**
   * One reaction, inside rsaml_run_arrival(): runs `body` after the busy work of the simulated
   * load and measures it as a job released by the arrival that started it, as the C++ runtime does.
   */
  void rsaml_run_reaction(const std::function<void()>& body);

 private:
  Schedule(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base, rclcpp::node_interfaces::NodeTimersInterface::SharedPtr timers,
           rclcpp::Clock::SharedPtr clock, double simulated_load, std::string module, int core);
  void busy(std::int64_t cpu_ns) const;
  /** What run_measured() measured of one job: the CPU time it used, and its stall. */
  struct Measured {
    std::int64_t execution_ns;
    std::int64_t stall_ns;  // its wall time (steady clock) minus its CPU time: ready, holding the node's lock, not running
  };
  /** Busy work of one job of modeled cost `cost_ns` (the simulated load), then `body`, under the node's lock: the CPU time both took, and the stall. */
  Measured run_measured(std::int64_t cost_ns, const std::function<void()>& body) const;
  /**
   * Counts one job of `jobs` released at `released` and done at `done` (on the node's clock), which
   * its executor called `latency_ns` after its release: its response, execution and stall, and a miss
   * or an overrun as it happens.
   */
  void record_job(Jobs& jobs, const rclcpp::Time& released, const rclcpp::Time& done, std::int64_t latency_ns,
                  const Measured& measured);

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base_;
  rclcpp::node_interfaces::NodeTimersInterface::SharedPtr timers_;
  rclcpp::Clock::SharedPtr clock_;
  std::string module_;
  int core_;
  double simulated_load_;
  rclcpp::Time started_;
  // The node's lock (a node is a lock group of the analysis), with priority inheritance where POSIX threads offer it
  // (rsaml/realtime.hpp, the C++ runtime's module lock class): a release at its real-time priority waits for a data
  // thread of priority 0 or the default priority only as long as that thread needs the lock (no priority inversion).
  rsaml_realtime::InheritingLock activation_;
  // The node's statistics, taken by its release threads and its data thread (priority 0, or the default priority for
  // aperiodic reactions): with priority inheritance, as the node's lock, so that a release never waits for a preempted
  // lower thread that holds it; held only to count a job and queue its lines, which are made before it is taken.
  rsaml_realtime::InheritingLock stats_;
  // Set under stats_ when the summary is written: a job done after it is neither counted nor said, so
  // that the summary's misses and the miss lines are the same jobs.
  bool summarized_ = false;
  std::atomic<bool> stopping_{false};  // set by rsaml_stop_releases(): the EDF release loops end
  std::deque<Release> releases_;
  std::deque<Arrivals> arrivals_;
  std::unique_ptr<Jobs> reactions_;  // null when the node does not react to data
  std::unique_ptr<Release> data_;    // the data arrivals' group and thread (rank 0); null without subscriptions
  rclcpp::Time arrived_;             // when the executor handed over the message being handled
  rclcpp::Time handled_;             // when its handling started (it held the node's lock)
};

/** The base of every generated plain node: an rclcpp node with its schedule. */
class ScheduledNode : public rclcpp::Node, public Schedule {
 public:
  ScheduledNode(const std::string& name, const rclcpp::NodeOptions& options, std::string module, int core)
      : rclcpp::Node(name, options), Schedule(static_cast<rclcpp::Node&>(*this), std::move(module), core) {}
};

/**
 * The executor threads of the releases and data arrivals of some nodes: each release's group, and
 * each node's data group, on a single-threaded executor of its own, on a thread pinned to the node's
 * core and at the release's real-time priority (rank 0 for the data) where the system permits it
 * (else it says so, once per thread, and runs at the default priority).
 */
class Scheduler {
 public:
  Scheduler() = default;
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  void add(Schedule& node);
  /** Stops and joins every thread (before the nodes are destroyed). */
  void stop();

 private:
  struct Worker {
    std::shared_ptr<rclcpp::Executor> executor;
    std::thread thread;
  };
  void serve(Release& jobs, Schedule& node);
  std::vector<Schedule*> nodes_;
  std::vector<std::unique_ptr<Worker>> workers_;
};

/**
 * main() of a node's own process: the node, its release and data threads, and a main executor for ROS 2's services;
 * a wrong argument or parameter ends it with one line and status 2 (run_main).
 */
template <typename NodeT>
int run_standalone(int argc, char** argv) {
  return run_main(argc, argv, [argc, argv] {
    init(argc, argv);
    {
      rclcpp::executors::SingleThreadedExecutor executor;
      auto node = std::make_shared<NodeT>(rclcpp::NodeOptions());
      Scheduler scheduler;
      scheduler.add(*node);
      executor.add_node(node->get_node_base_interface());
      spin(executor);
      scheduler.stop();
    }
    rclcpp::shutdown();
    return 0;
  });
}

}  // namespace rsaml_ros2
