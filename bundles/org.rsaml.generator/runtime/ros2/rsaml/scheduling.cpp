/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
#include "rsaml/scheduling.hpp"
#include "rsaml/jobs.hpp"
#include "rsaml/realtime.hpp"
#include "rsaml/tracequeue.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <unordered_map>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace rsaml_ros2 {

namespace {

/**
 * The process's trace (this package's copy of it): a queue a writer thread writes out (rsaml/tracequeue.hpp), so that
 * no thread that traces, a release under the node's statistics lock included, ever waits for standard output. Made by
 * init(), or by the first node, on the thread that makes the nodes; stamps from when it is made.
 */
rsaml_trace::TraceQueue& trace_queue() {
  static rsaml_trace::TraceQueue lines;
  return lines;
}
std::mutex registry_mutex;
std::unordered_map<const rclcpp::node_interfaces::NodeBaseInterface*, Schedule*> registry;
std::atomic<int> stop_signals{0};
std::chrono::milliseconds shutdown_grace{GRACE_WITHOUT_ARGUMENT_MS};

void on_stop_signal(int) { stop_signals.fetch_add(1); }

std::string ms(std::int64_t ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", static_cast<double>(ns) / 1e6);
  return text;
}

std::int64_t thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

/** The calling thread under `release`'s fixed priority (SCHED_FIFO or SCHED_RR at its rank); 0 or the error. */
int fixed_priority(const Release& release) {
  const int policy = release.round_robin ? SCHED_RR : SCHED_FIFO;
  const int low = sched_get_priority_min(policy);
  const int high = sched_get_priority_max(policy);
  sched_param param{};
  param.sched_priority = std::min(low + release.rank, high);
  return low < 0 || high < low ? EINVAL : pthread_setschedparam(pthread_self(), policy, &param);
}

#if defined(__linux__)
/**
 * The CPU of the node's core in this process: the one the launch placed the process on (RSAML_CPU, which its prefix
 * sets with the process's taskset: on one machine that runs every host, another host's core is on a CPU of its own,
 * OneMachineCpus), so that the node's threads stay where the launch put the process; else (started otherwise, e.g.
 * by ros2 run) the core itself.
 */
int cpu_of(int core) {
  const char* placed = core >= 0 ? std::getenv("RSAML_CPU") : nullptr;
  if (placed != nullptr && *placed != '\0') {
    char* end = nullptr;
    const long cpu = std::strtol(placed, &end, 10);
    if (*end == '\0' && cpu >= 0 && cpu < CPU_SETSIZE) {
      return static_cast<int>(cpu);
    }
  }
  return core;
}

/** The calling thread on `cpu` alone; false where the machine has no such CPU (or refuses). */
bool pin(int cpu) {
  if (cpu < 0 || cpu >= CPU_SETSIZE) {
    return false;
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}
#endif

/**
 * Pins the calling thread to the CPU of `core` (when >= 0: cpu_of) and gives it the release's real-time priority; a
 * release of an EDF processor is then given every CPU the process may use (the kernel admits a deadline thread only on
 * every CPU of its root domain) and waits for its first release at its rank, where it asks for SCHED_DEADLINE
 * (Schedule::rsaml_run_deadline), which puts it back on its CPU where the kernel refuses. Says which in the trace.
 */
void place(Release& release, int core) {
#if defined(__linux__)
  release.cpu = cpu_of(core);
  if (core >= 0) {
    const bool pinned = pin(release.cpu);
    trace("cpu " + release.label + " core " + std::to_string(core) +
          (release.cpu == core ? "" : " on CPU " + std::to_string(release.cpu) + " (where the launch placed its process)") +
          (pinned ? "" : " not available: default"));
    if (!pinned) {
      release.cpu = -1;
    }
  }
  if (release.edf && release.cpu >= 0) {
    cpu_set_t all;
    CPU_ZERO(&all);
    // every CPU the process's main thread may use: more than its core's, unless the process was placed there alone
    if (sched_getaffinity(getpid(), sizeof all, &all) == 0 && CPU_COUNT(&all) > 1 &&
        pthread_setaffinity_np(pthread_self(), sizeof all, &all) == 0) {
      release.unpinned = " on every CPU of its process, not CPU " + std::to_string(release.cpu) + " alone";
    }
  }
  if (!release.realtime) {
    release.sched = "default (aperiodic reactions)";
    trace("sched " + release.label + " default: it serves aperiodic reactions, whose load the model does not bound, below every"
          " real-time thread");
    return;
  }
  const int error = fixed_priority(release);
  const std::string instead = release.sched.empty() ? "" : " " + release.sched;
  if (error == 0) {
    release.sched = std::string(release.round_robin ? "SCHED_RR" : "SCHED_FIFO") + " rank " + std::to_string(release.rank) + instead;
    trace("sched " + release.label + " " + release.sched);
  } else {
    release.sched = "default" + instead;
    trace("sched " + release.label + " default" + instead + ": real-time priority not permitted (" + std::strerror(error) +
          "); it runs at the default priority and the timing analysis's verdicts do not hold (give the process"
          " CAP_SYS_NICE or an rtprio limit, e.g. ulimit -r 99)");
  }
#else
  (void)core;
  release.sched = "default";
  trace("sched " + release.label + " default: not supported on this platform");
#endif
}

}  // namespace

void trace(const std::string& text) { trace_queue().post(text); }

void init(int argc, char** argv) {
  const std::string option = GRACE_OPTION;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--ros-args") {
      break;
    }
    if (arg.rfind(option + "=", 0) == 0) {
      const std::string value = arg.substr(option.size() + 1);
      char* end = nullptr;
      errno = 0;
      const long long grace = std::strtoll(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || grace < 0 || errno == ERANGE) {
        throw UsageError("argument " + arg + ": not a whole number of milliseconds (0 or more); give how long the process"
                         " serves its managed nodes after SIGINT, e.g. " + option +
                         "=3000 (the launch files set it from the number of managed nodes)");
      }
      shutdown_grace = std::chrono::milliseconds(grace);
    }
  }
  trace_queue();  // its writer made here, at the default priority, before any release thread
  usage_detail::before_abort() = [] { trace_queue().flush(); };  // the lines before an uncaught exception not lost
  rclcpp::init(argc, argv, rclcpp::InitOptions(), rclcpp::SignalHandlerOptions::None);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
}

void spin(rclcpp::Executor& executor) {
  while (stop_signals.load() == 0 && rclcpp::ok()) {
    executor.spin_once(std::chrono::milliseconds(100));
  }
  const auto until = std::chrono::steady_clock::now() + shutdown_grace;
  std::vector<std::string> configured = Schedule::rsaml_configured();
  const bool managed = !configured.empty();
  while (!configured.empty() && stop_signals.load() < 2 && rclcpp::ok() && std::chrono::steady_clock::now() < until) {
    executor.spin_once(std::chrono::milliseconds(20));
    configured = Schedule::rsaml_configured();
  }
  // The last cleanup's answer is on its way to the lifecycle manager: a moment more for its delivery.
  const auto linger = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (managed && configured.empty() && stop_signals.load() < 2 && rclcpp::ok() && std::chrono::steady_clock::now() < linger) {
    executor.spin_once(std::chrono::milliseconds(20));
  }
  for (const std::string& node : configured) {
    trace("state " + node + " at exit: no lifecycle manager deactivated it");
  }
}

Schedule::Schedule(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base,
                   rclcpp::node_interfaces::NodeTimersInterface::SharedPtr timers, rclcpp::Clock::SharedPtr clock,
                   double simulated_load, std::string module, int core)
    : base_(std::move(base)), timers_(std::move(timers)), clock_(std::move(clock)), module_(std::move(module)), core_(core),
      simulated_load_(simulated_load) {
  if (!(simulated_load_ >= 0.0 && simulated_load_ <= 1.0)) {
    char given[32];
    std::snprintf(given, sizeof given, "%g", simulated_load_);
    throw UsageError("node " + std::string(base_->get_fully_qualified_name()) + ": parameter rsaml.simulated_load is " + given +
                     ": it must be a fraction from 0 to 1 of the modeled execution time; set it so"
                     " (launch argument simulated_load:=, or -p rsaml.simulated_load:=0.5)");
  }
  started_ = clock_->now();
  trace_queue();  // in a container not of this package, made by the thread that loads the node
  std::lock_guard<std::mutex> lock(registry_mutex);
  registry[base_.get()] = this;
}

Schedule::~Schedule() {
  {
    std::lock_guard<std::mutex> lock(registry_mutex);
    registry.erase(base_.get());
  }
  // The summary's lines made under stats_ (no job is counted or said after it: summarized_), written after it is let
  // go, each waiting for room in the trace's queue rather than dropped: behind every miss line of a job it counts.
  std::vector<std::string> lines;
  {
    std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
    summarized_ = true;
    // The summary line, written by the C++ runtime's writer (rsaml/jobs.hpp), after the lines of the jobs over the plain bound.
    auto summary = [&lines](const Jobs& r) {
      rsaml_jobs::Observed o;
      o.label = r.label;
      o.jobs = r.jobs;
      o.first_release_ns = r.first_release_ns;
      o.last_release_ns = r.last_release_ns;
      o.misses = r.misses;
      o.overruns = r.overruns;
      o.worst_response_ns = r.worst_response_ns;
      o.bound_ns = r.bound_ns;
      o.deadline_ns = r.deadline_ns;
      o.worst_execution_ns = r.worst_execution_ns;
      o.modeled_ns = r.cost_ns;
      o.worst_start_latency_ns = r.worst_latency_ns;
      o.worst_stall_ns = r.worst_stall_ns;
      o.sched = r.sched;
      o.worst_job = r.worst_job;
      o.over_bound = r.over_bound;
      o.listed = r.listed;
      for (std::string& line : rsaml_jobs::over_bound_lines(o)) {
        lines.push_back(std::move(line));
      }
      lines.push_back(rsaml_jobs::line(o));
    };
    for (const Release& r : releases_) {
      summary(r);
      if (r.executor_jobs > 0) {
        lines.push_back("executor " + r.label + " jobs " + std::to_string(r.executor_jobs) + " worst " + ms(r.executor_worst_ns) +
                        " ms mean " + ms(r.executor_total_ns / static_cast<std::int64_t>(r.executor_jobs)) +
                        " ms (its thread's CPU time between two jobs)");
      }
    }
    if (reactions_) {
      if (data_) {  // the scheduling of the thread that ran them (its executor is stopped by now)
        reactions_->sched = data_->sched.empty() ? "default (never scheduled)" : data_->sched;
      }
      summary(*reactions_);
    }
    for (const Arrivals& a : arrivals_) {
      lines.push_back("summary " + module_ + ":" + a.port + " messages " + std::to_string(a.messages) + " received " +
                      (a.messages > 0 ? ms(a.first_ns) + ".." + ms(a.last_ns) : std::string("none")) + " ms");
    }
  }
  for (const std::string& line : lines) {
    trace_queue().post_waiting(line);
  }
  trace_queue().post_dropped_in_all();
  trace_queue().flush();
}

Schedule* Schedule::rsaml_of(const rclcpp::node_interfaces::NodeBaseInterface* base) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  auto found = registry.find(base);
  return found == registry.end() ? nullptr : found->second;
}

std::vector<std::string> Schedule::rsaml_configured() {
  std::vector<std::string> configured;
  std::lock_guard<std::mutex> lock(registry_mutex);
  for (const auto& entry : registry) {
    const char* state = entry.second->rsaml_configured_state();
    if (state != nullptr) {
      configured.push_back(entry.second->module_ + " " + state);
    }
  }
  std::sort(configured.begin(), configured.end());
  return configured;
}

std::size_t Schedule::rsaml_add_release(const std::string& label, int rank, bool round_robin, std::int64_t deadline_ns,
                                        std::int64_t cost_ns, std::int64_t period_ns, std::int64_t bound_ns, bool edf) {
  Release& r = releases_.emplace_back();  // in place: a release's thread state (atomics) never moves
  r.label = label;
  r.rank = rank;
  r.round_robin = round_robin;
  r.edf = edf;
  r.period_ns = period_ns;
  r.deadline_ns = deadline_ns;
  r.cost_ns = cost_ns;
  r.bound_ns = bound_ns;
  r.group = base_->create_callback_group(rclcpp::CallbackGroupType::MutuallyExclusive, false);
  return releases_.size() - 1;
}

void Schedule::rsaml_count_dropped(std::size_t release, std::int64_t period_ns, const rclcpp::Time& expected, const rclcpp::Time& called) {
  const std::int64_t first = (expected - started_).nanoseconds() + period_ns;
  const std::int64_t until = (called - started_).nanoseconds();
  if (period_ns <= 0 || first >= until) {
    return;
  }
  const std::int64_t dropped = (until - first + period_ns - 1) / period_ns;  // first + k * period < until
  const std::int64_t last = first + (dropped - 1) * period_ns;
  // The late release and its call placed on CLOCK_MONOTONIC, the platform monitor's clock (the node's clock may be
  // the system's), so that a check can hold the late call against what the platform took at that moment.
  const std::int64_t now_monotonic = rsaml_jobs::monotonic_ns();
  const rclcpp::Time now = clock_->now();
  const std::int64_t expected_monotonic = now_monotonic - (now - expected).nanoseconds();
  const std::int64_t called_monotonic = now_monotonic - (now - called).nanoseconds();
  Release& r = releases_[release];
  const std::string line = "miss " + r.label + " released " + ms(first) + (dropped > 1 ? ".." + ms(last) : std::string()) +
                           " ms not run (" + std::to_string(dropped) + (dropped > 1 ? " releases" : " release") +
                           "): ROS 2's timer dropped " + (dropped > 1 ? "them" : "it") + ", as its previous release was called " +
                           ms((called - expected).nanoseconds()) + " ms late (on CLOCK_MONOTONIC: released " +
                           std::to_string(expected_monotonic) + " ns, called " + std::to_string(called_monotonic) + " ns)";
  // counted and said under one lock, before the summary or not at all
  std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
  if (summarized_) {
    return;
  }
  r.jobs += static_cast<std::uint64_t>(dropped);
  r.misses += static_cast<std::uint64_t>(dropped);
  r.last_release_ns = last;
  trace(line);
}

bool Schedule::rsaml_run_deadline(std::size_t release, rclcpp::TimerBase& timer, const rclcpp::Time& called,
                                  const std::function<void()>& body) {
  Release& r = releases_[release];
#if defined(__linux__)
  // A thread still under SCHED_DEADLINE asking again with the same parameters would keep its old periods: it leaves
  // SCHED_DEADLINE first, so that its first period begins now (the loop below leaves it when it ends).
  if (sched_getscheduler(0) == static_cast<int>(rsaml_realtime::kSchedDeadline)) {
    fixed_priority(r);
  }
  const rclcpp::Time asked = clock_->now();
  // Under simulated time (use_sim_time) the timer releases the jobs at the simulation's rate, while the kernel's periods
  // are the machine's: the release stays at its rank, timer-driven, as every other node follows the simulation.
  const bool simulated = clock_->get_clock_type() == RCL_ROS_TIME && clock_->ros_time_is_active();
  std::string refused = simulated ? "simulated time (use_sim_time) releases its jobs, while SCHED_DEADLINE's periods are the machine's"
                                  : rsaml_realtime::request_deadline(r.cost_ns, r.deadline_ns, r.period_ns, rsaml_realtime::kFlagReclaim);
  std::string how = ", reclaiming";
  if (!refused.empty() && !simulated) {
    const std::string with_flag = refused;
    refused = rsaml_realtime::request_deadline(r.cost_ns, r.deadline_ns, r.period_ns);
    how = " (without reclaiming: " + with_flag + ")";
  }
  std::string sched;
  if (refused.empty()) {
    sched = "SCHED_DEADLINE runtime " + ms(r.cost_ns) + " ms deadline " + ms(r.deadline_ns) + " ms period " + ms(r.period_ns) + " ms" +
            how + ", its periods from its first release (asked " + ms(std::max<std::int64_t>(0, (asked - called).nanoseconds())) +
            " ms after it), each job released by the kernel's next period, not by the timer" + r.unpinned + " (kernel: " +
            rsaml_realtime::kernel_policy() + ")";
  } else {
    const int error = fixed_priority(r);
    sched = (error == 0 ? std::string(r.round_robin ? "SCHED_RR" : "SCHED_FIFO") + " rank " + std::to_string(r.rank) : "default") +
            " instead of EDF: " + refused;
    if (!r.unpinned.empty()) {
      // back on its CPU, as its cpu line says (the C++ runtime's fallback does the same)
      sched += pin(r.cpu) ? ", back on CPU " + std::to_string(r.cpu) + " alone" : ", left on every CPU of its process (CPU " +
                                                                                      std::to_string(r.cpu) + " refused)";
      r.unpinned.clear();
    }
  }
  {
    std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
    r.sched = sched;
  }
  trace("sched " + r.label + " " + sched);
  if (!refused.empty()) {
    return false;
  }
  r.deadline_tid.store(static_cast<long>(syscall(SYS_gettid)));
  // Its releases counted from the request, as the C++ runtime's: the kernel's first period began as it granted it (at or a
  // few microseconds after `asked`), so a response counted from there is never short; every period one more. Whether a
  // job ended before its next release is decided on CLOCK_MONOTONIC, as the kernel's periods run: the node's clock (the
  // system's, or a simulated one) may step or stand still, and a loop deciding on it would then run a backlog of jobs
  // back to back, or yield past a late job. The releases are measured on the node's clock, as every other job's.
  const rclcpp::Duration period = rclcpp::Duration::from_nanoseconds(r.period_ns);
  rclcpp::Time released = asked;
  std::int64_t released_monotonic = rsaml_jobs::monotonic_ns() - (clock_->now() - asked).nanoseconds();
  while (!stopping_.load() && !timer.is_canceled() && rclcpp::ok()) {
    rsaml_run_job(release, released, clock_->now(), body);
    released = released + period;
    released_monotonic += r.period_ns;
    // the kernel's next period, unless the job ended past its next release (then the next job starts at once)
    if (rsaml_jobs::monotonic_ns() < released_monotonic) {
      r.yielding.store(true);
      if (!stopping_.load()) {
        sched_yield();  // the rest of its runtime given up: it runs again at the kernel's next period, its next release
      }
      r.yielding.store(false);
    }
  }
  // Back at its rank (the kernel's bandwidth given back); a stopped release's timer is cancelled, so that its executor
  // calls it no more.
  r.deadline_tid.store(0);
  fixed_priority(r);
  if (!timer.is_canceled()) {
    timer.cancel();
  }
  return true;
#else
  (void)timer;
  (void)called;
  (void)body;
  {
    std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
    r.sched += " instead of EDF: SCHED_DEADLINE is Linux's";
  }
  return false;
#endif
}

void Schedule::rsaml_stop_releases() {
  stopping_.store(true);
#if defined(__linux__)
  for (Release& r : releases_) {
    // stopping_ is set: a thread seen waiting here starts no job when it resumes; its tid is set before it yields
    const long tid = r.deadline_tid.load();
    if (r.yielding.load() && tid != 0) {
      sched_param param{};
      sched_setscheduler(static_cast<pid_t>(tid), SCHED_OTHER, &param);
    }
  }
#endif
}

std::size_t Schedule::rsaml_add_arrivals(const std::string& port) {
  Arrivals a;
  a.port = port;
  arrivals_.push_back(std::move(a));
  return arrivals_.size() - 1;
}

rclcpp::CallbackGroup::SharedPtr Schedule::rsaml_data_group() {
  if (!data_) {
    data_ = std::make_unique<Release>();
    data_->label = module_ + " worker";
    data_->rank = 0;  // priority 0 of the analysis: SCHED_FIFO's lowest priority, below every release (rank 1 and up)
    data_->group = base_->create_callback_group(rclcpp::CallbackGroupType::MutuallyExclusive, false);
  }
  return data_->group;
}

void Schedule::rsaml_data_unbounded() {
  rsaml_data_group();
  data_->realtime = false;
}

void Schedule::busy(std::int64_t cpu_ns) const {
  const std::int64_t until = thread_cpu_ns() + cpu_ns;
  while (thread_cpu_ns() < until) {
  }
}

Schedule::Measured Schedule::run_measured(std::int64_t cost_ns, const std::function<void()>& body) const {
  const auto wall = std::chrono::steady_clock::now();
  const std::int64_t cpu = thread_cpu_ns();
  const std::int64_t busy_ns = rsaml_jobs::busy_work_ns(cost_ns, simulated_load_);
  if (busy_ns > 0) {
    busy(busy_ns);
  }
  body();
  const std::int64_t execution = thread_cpu_ns() - cpu;
  const std::int64_t elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - wall).count();
  return Measured{execution, std::max<std::int64_t>(0, elapsed - execution)};
}

void Schedule::record_job(Jobs& r, const rclcpp::Time& released, const rclcpp::Time& done, std::int64_t latency_ns,
                          const Measured& measured) {
  const std::int64_t done_monotonic = rsaml_jobs::monotonic_ns();  // a moment after `done`, on the platform monitor's clock
  const std::int64_t execution_ns = measured.execution_ns;
  const std::int64_t response = (done - released).nanoseconds();
  const std::int64_t at = (released - started_).nanoseconds();
  // Its miss and overrun lines made before the lock, which is held only to count the job and queue them.
  const bool missed = r.deadline_ns > 0 && response > r.deadline_ns;
  const bool overran = r.cost_ns > 0 && execution_ns > r.cost_ns;
  const std::string miss_line =
      missed ? "miss " + r.label + " released " + ms(at) + " ms response " + ms(response) + " ms deadline " + ms(r.deadline_ns) + " ms"
             : std::string();
  const std::string overrun_line =
      overran ? "overrun " + r.label + " released " + ms(at) + " ms execution " + ms(execution_ns) + " ms modeled " + ms(r.cost_ns) + " ms"
              : std::string();
  // Counted and said under one lock: a job done after the summary is neither (the summary's misses are the miss lines).
  std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
  if (summarized_) {
    return;
  }
  if (r.jobs++ == 0) {
    r.first_release_ns = at;
    r.listed.reserve(rsaml_jobs::LISTED);
  }
  r.last_release_ns = at;
  r.worst_response_ns = std::max(r.worst_response_ns, response);
  r.worst_execution_ns = std::max(r.worst_execution_ns, execution_ns);
  r.worst_latency_ns = std::max(r.worst_latency_ns, latency_ns);
  r.worst_stall_ns = std::max(r.worst_stall_ns, measured.stall_ns);
  // the node's clock may be the system's: the release placed on CLOCK_MONOTONIC by its response
  rsaml_jobs::record_instant(done_monotonic - response, done_monotonic, r.bound_ns, r.worst_job, r.over_bound, r.listed);
  if (missed) {
    ++r.misses;
    trace(miss_line);
  }
  if (overran) {
    ++r.overruns;
    trace(overrun_line);
  }
}

void Schedule::rsaml_run_job(std::size_t release, const rclcpp::Time& released, const rclcpp::Time& called,
                             const std::function<void()>& body) {
  const std::int64_t started_cpu = thread_cpu_ns();
  Release& r = releases_[release];
  Measured measured{};
  {
    std::lock_guard<rsaml_realtime::InheritingLock> lock(activation_);
    measured = run_measured(r.cost_ns, body);
  }
  record_job(r, released, clock_->now(), (called - released).nanoseconds(), measured);
  // The executor's own CPU time since the previous job ended (waking, taking the timer, dispatching), measured, not modeled.
  const std::int64_t ended_cpu = thread_cpu_ns();
  std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
  if (r.job_end_cpu_ns >= 0) {
    const std::int64_t executor = started_cpu - r.job_end_cpu_ns;
    ++r.executor_jobs;
    r.executor_worst_ns = std::max(r.executor_worst_ns, executor);
    r.executor_total_ns += executor;
  }
  r.job_end_cpu_ns = ended_cpu;
}

void Schedule::rsaml_run_arrival(std::size_t port, const std::function<void()>& body) {
  const rclcpp::Time arrived = clock_->now();
  {
    std::lock_guard<rsaml_realtime::InheritingLock> lock(activation_);
    arrived_ = arrived;
    handled_ = clock_->now();
    body();
  }
  const std::int64_t at = (arrived - started_).nanoseconds();
  std::lock_guard<rsaml_realtime::InheritingLock> lock(stats_);
  Arrivals& a = arrivals_[port];
  ++a.messages;
  if (a.first_ns < 0) {
    a.first_ns = at;
  }
  a.last_ns = at;
}

void Schedule::rsaml_measure_reactions(const std::string& label, std::int64_t deadline_ns, std::int64_t cost_ns,
                                       std::int64_t bound_ns) {
  reactions_ = std::make_unique<Jobs>();
  reactions_->label = label;
  reactions_->deadline_ns = deadline_ns;
  reactions_->cost_ns = cost_ns;
  reactions_->bound_ns = bound_ns;
  reactions_->sched = "default (no data arrives)";
}

void Schedule::rsaml_run_reaction(const std::function<void()>& body) {
  if (!reactions_) {
    body();
    return;
  }
  // Under the node's lock (in rsaml_run_arrival): arrived_ and handled_ are the current arrival's.
  const Measured measured = run_measured(reactions_->cost_ns, body);
  record_job(*reactions_, arrived_, clock_->now(), (handled_ - arrived_).nanoseconds(), measured);
}

Scheduler::~Scheduler() { stop(); }

void Scheduler::add(Schedule& node) {
  nodes_.push_back(&node);
  for (Release& r : node.rsaml_releases()) {
    serve(r, node);
  }
  if (node.rsaml_data() != nullptr) {
    serve(*node.rsaml_data(), node);
  }
}

void Scheduler::serve(Release& jobs, Schedule& node) {
  auto worker = std::make_unique<Worker>();
  auto executor = std::make_shared<rclcpp::executors::SingleThreadedExecutor>();
  executor->add_callback_group(jobs.group, node.rsaml_base());
  worker->executor = executor;
  Release* release = &jobs;
  const int core = node.rsaml_core();
  worker->thread = std::thread([executor, release, core] {
    place(*release, core);
    executor->spin();
  });
  workers_.push_back(std::move(worker));
}

void Scheduler::stop() {
  for (Schedule* node : nodes_) {
    node->rsaml_stop_releases();  // the EDF release loops, which never return to their executors, end first
  }
  nodes_.clear();
  for (auto& w : workers_) {
    while (!w->executor->is_spinning() && rclcpp::ok()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    w->executor->cancel();
  }
  for (auto& w : workers_) {
    if (w->thread.joinable()) {
      w->thread.join();
    }
  }
  workers_.clear();
}

}  // namespace rsaml_ros2
