/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// RsaML's runtime for generated architectures: timed releases, data flow between modules,
// inhibitors and suppressors, and a trace of the run on standard output.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace rsaml {

using Clock = std::chrono::steady_clock;
using Nanos = std::chrono::nanoseconds;

/** The command line of a generated program. */
struct Options {
  long long run_for_ms = -1;  // negative: until interrupted (Ctrl-C, SIGTERM)
  bool trace = true;
  bool realtime = true;
  /** Percent of its modeled execution time each timed job first consumes on the CPU (0: none). */
  long long busy_work_percent = 0;
  bool exit = false;  // --help or a bad argument: exit with status
  int status = 0;
};

Options parse_options(int argc, char** argv, const char* program);

/** One line per event on standard output, after the milliseconds since the start of the run. */
class Trace {
 public:
  static void configure(bool enabled, Clock::time_point start);
  static bool enabled();
  static void line(const std::string& text);
  /** A line of the run's report (deadline misses, overruns, the summary): printed even when the trace is off. */
  static void report(const std::string& text);
  static void flush();
};

/**
 * Scheduling policy of a timed release: SCHED_FIFO or SCHED_RR at its rank, or (the releases of an
 * EDF processor) SCHED_DEADLINE where the kernel permits it, SCHED_FIFO at the rank otherwise.
 */
enum class Policy { Fifo, RoundRobin, Deadline };

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
  Clock::time_point first_release{};  // of the first job; the summary gives it and the last since the run's start
  Clock::time_point last_release{};
};

class System;
class Module;

/** A module's reactions and what its worker thread observed of them. */
struct Reactions {
  Module* module;
  std::string label;
  JobBounds bounds;
  std::string sched;  // the scheduling the worker got, as the trace says it
  JobStats stats;
};

/**
 * An inhibitor or a suppressor: active for its duration after the last message on its trigger port
 * that asserts it (see asserts()). Links are shared between threads, so their state is a single
 * atomic time.
 */
class Link {
 public:
  Link(std::string name, Nanos duration);
  const std::string& name() const { return name_; }
  void trigger();
  bool active() const;

 private:
  std::string name_;
  Nanos duration_;
  std::atomic<Clock::rep> until_;
};

/**
 * The work a module is doing, on the current thread: the module's lock is held, and data sent
 * belongs to the activation's wave (a timed release or the start starts a wave; data carries it on,
 * and a module reacts at most once per wave, so cycles of reacting modules end).
 */
class Activation {
 public:
  Activation(Module& module, std::uint64_t wave, bool timed, Clock::time_point release);
  ~Activation();
  Activation(const Activation&) = delete;
  Activation& operator=(const Activation&) = delete;
  static Activation* current();

  Module& module;
  const std::uint64_t wave;
  const bool timed;
  const Clock::time_point release;
  std::unique_lock<std::recursive_mutex> lock;

 private:
  Activation* previous_;
};

/** The base of every generated module class. */
class Module {
 public:
  /**
   * core: the CPU core the module's threads are pinned to (its processor's), or -1 for the OS's
   * choice; host: its processor's host, "" for the main host; cpu: the CPU of this machine its core
   * is, when this one program runs several hosts' processors (-1: the core's own number).
   */
  Module(System& system, std::string name, int core = -1, std::string host = "", int cpu = -1);
  virtual ~Module();
  Module(const Module&) = delete;
  Module& operator=(const Module&) = delete;

  /** layer/module, as in the model. */
  const std::string& name() const { return name_; }
  System& system() { return system_; }
  int core() const { return core_; }
  const std::string& host() const { return host_; }
  /** The CPU of this machine its threads are pinned to: its core, or another host's core's CPU here. */
  int cpu() const { return cpu_; }

  // Used by the runtime and the generated code.
  void post(std::uint64_t wave, std::function<void()> work);
  void start_worker();
  void stop_worker();
  void start_step(std::uint64_t wave);
  /**
   * Measures the module's reactions (a module that reacts to data calls it once, in its constructor):
   * each from the arrival that starts it to its completion, against bounds.
   */
  void measure_reactions(std::string label, JobBounds bounds);
  /**
   * A reaction to the data that has arrived: runs body (the step functions and the sending of the
   * outputs) when begin_reaction() lets it, after the busy work, and measures it.
   */
  void react(Nanos min_interval, const std::function<void()>& body);
  /** Runs one job of a timed release; busy: CPU time it consumes first (the --busy-work stand-in for user code). */
  void timed_release(const std::string& label, Clock::time_point release, const std::function<void()>& body,
                     Nanos busy = Nanos(0));
  /** Registers an entry port's latch: each activation starts with the latest value of every port. */
  void add_input(std::function<void()> latch) { latches_.push_back(std::move(latch)); }

 protected:
  /** Called once when the run starts, lowest layer first, before the outputs are first sent. */
  virtual void on_start() {}
  /** Sends every output port's value; called after each activation. */
  virtual void publish_outputs() {}
  /** Runs an action; in a timed release, first waits until the action's offset in the period. */
  void run_action(const char* label, Nanos offset, const std::function<void()>& body);
  /**
   * Whether the data that started the current activation starts a reaction: once per wave, and its
   * arrival not sooner than min_interval after the arrival that started the previous reaction.
   */
  bool begin_reaction(Nanos min_interval);
  /** Whether a sporadic function may run again (and, if so, notes that it runs now). */
  static bool due(Clock::time_point& last, Nanos min_interval);
  /** Adds a line to the run's trace. */
  void trace(const std::string& text) const;

 private:
  friend class Activation;
  struct Mail {
    std::uint64_t wave;
    Clock::time_point arrived;
    std::function<void()> work;
  };
  void run_worker();

  System& system_;
  std::string name_;
  int core_;
  std::string host_;
  int cpu_;
  std::recursive_mutex mutex_;
  std::mutex mail_mutex_;
  std::condition_variable mail_cv_;
  std::deque<Mail> mail_;
  bool stopping_ = false;
  std::thread worker_;
  std::set<std::uint64_t> waves_;
  std::vector<std::function<void()>> latches_;
  int depth_ = 0;
  Clock::time_point last_reaction_{};
  bool reacted_ = false;
  Reactions* reactions_ = nullptr;  // owned by the system; null when not measured
};

template <class T>
class Input;

/**
 * Whether a message on a link's trigger port asserts the link: a boolean only when true, a message
 * of any other data kind always (its arrival is the event). A message that does not assert has no
 * effect on the link and does not replace a suppressor's target input.
 */
template <class T>
bool asserts(const T&) {
  return true;
}
inline bool asserts(bool value) { return value; }

/** An output port: set value, and publish_outputs() sends it; or send() at once. */
template <class T>
class Output {
 public:
  Output(Module& owner, const std::string& port) : owner_(owner), name_(owner.name() + "." + port) {}
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  /** The value publish_outputs() sends. */
  T value{};

  void send() { send(value); }
  void send(const T& data);

  const std::string& name() const { return name_; }
  /** How many messages this port has sent (inhibited ones included). */
  std::uint64_t sent() const { return sequence_.load(); }

  // Wiring, by the generated architecture before the run starts.
  void connect(Input<T>& target) { routes_.push_back(Route{&target, nullptr}); }
  void inhibited_by(Link& link) { inhibitors_.push_back(&link); }
  void triggers(Link& link) { triggers_.push_back(&link); }
  /** A suppressor triggered by this port, whose messages replace the target's input. */
  void triggers(Link& link, Input<T>& replaced) {
    triggers_.push_back(&link);
    routes_.push_back(Route{&replaced, &link});
  }

 private:
  struct Route {
    Input<T>* target;
    Link* replacing;
  };
  Module& owner_;
  std::string name_;
  std::vector<Route> routes_;
  std::vector<Link*> inhibitors_;
  std::vector<Link*> triggers_;
  std::atomic<std::uint64_t> sequence_{0};
};

/**
 * An entry port: the latest value received. A value sent is at once the one the owning module's next
 * activation reads (taken when the activation starts, so it does not change during it: the sampling
 * the timing analysis assumes); the handler runs on the owning module's thread.
 */
template <class T>
class Input {
 public:
  using Handler = std::function<void(const T&)>;
  Input(Module& owner, const std::string& port, Handler handler)
      : owner_(owner), name_(owner.name() + "." + port), handler_(std::move(handler)) {
    owner_.add_input([this] { latch(); });
  }
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;

  /** The latest value received (a default value before the first). */
  const T& value() const { return value_; }
  /** How many values have arrived. */
  std::uint64_t received() const { return received_; }
  const std::string& name() const { return name_; }

  void suppressed_by(Link& link) { suppressors_.push_back(&link); }
  Link* active_suppressor() const {
    for (Link* link : suppressors_) {
      if (link->active()) {
        return link;
      }
    }
    return nullptr;
  }

  void deliver(const T& data, const std::string* from, std::uint64_t sequence, std::uint64_t wave, Link* replacing) {
    {
      std::lock_guard<std::mutex> lock(pending_mutex_);
      pending_ = data;
      fresh_ = true;
    }
    owner_.post(wave, [this, data, from, sequence, replacing] {
      ++received_;
      if (Trace::enabled()) {
        Trace::line("recv " + name_ + " <- " + *from + " #" + std::to_string(sequence) +
                    (replacing ? " by " + replacing->name() : std::string()));
      }
      handler_(data);
    });
  }

 private:
  /** Called with the owner's lock held, when one of its activations starts. */
  void latch() {
    std::lock_guard<std::mutex> lock(pending_mutex_);
    if (fresh_) {
      value_ = pending_;
      fresh_ = false;
    }
  }

  Module& owner_;
  std::string name_;
  Handler handler_;
  std::vector<Link*> suppressors_;
  T value_{};
  std::mutex pending_mutex_;
  T pending_{};
  bool fresh_ = false;
  std::uint64_t received_ = 0;
};

/** The running architecture: its modules, their timed releases, the start and the stop. */
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
   * SCHED_FIFO at the lowest real-time priority where permitted. Says which in the trace.
   */
  std::string schedule_worker(const std::string& module);
  /** The record of a module's measured reactions (see Module::measure_reactions). */
  Reactions& reactions(Module& module, std::string label, JobBounds bounds);
  /** Measures one reaction, as job_done does a release's job. */
  void reaction_done(Reactions& reactions, Clock::time_point arrived, Clock::time_point started, Clock::time_point done,
                     Nanos cpu);
  /** CPU time the --busy-work option has a job of modeled cost consume. */
  Nanos busy_work(Nanos cost) const;
  /** Sleeps until t; false when the run is stopping. */
  bool sleep_until(Clock::time_point t);
  bool stopping() const { return stopping_.load(); }
  std::uint64_t new_wave() { return waves_.fetch_add(1) + 1; }

 private:
  struct Release {
    Module* module;
    std::string label;
    Nanos period;
    Nanos offset;
    Policy policy;
    int rank;
    JobBounds bounds;
    std::function<void()> body;
    std::thread thread;
    std::string sched;  // the scheduling it got, as the trace says it
    JobStats stats;
  };
  void run_release(Release& release);
  /** Gives the calling release thread its core and its scheduling; says which in the trace. */
  void schedule_self(Release& release);
  /** Measures one job: its response (release to completion) and execution (thread CPU) time. */
  void job_done(Release& release, Clock::time_point released, Clock::time_point done, Nanos cpu);
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

template <class T>
void Output<T>::send(const T& data) {
  Activation* activation = Activation::current();
  const std::uint64_t wave = activation ? activation->wave : owner_.system().new_wave();
  const std::uint64_t sequence = ++sequence_;
  for (Link* link : inhibitors_) {
    if (link->active()) {
      if (Trace::enabled()) {
        Trace::line("inhibit " + name_ + " #" + std::to_string(sequence) + " by " + link->name());
      }
      return;
    }
  }
  const bool asserting = asserts(data);
  if (asserting) {
    for (Link* link : triggers_) {
      link->trigger();
    }
  }
  if (Trace::enabled()) {
    Trace::line("send " + name_ + " #" + std::to_string(sequence));
  }
  for (const Route& route : routes_) {
    if (route.replacing && !asserting) {
      continue;  // only an asserting message replaces the suppressed input
    }
    if (!route.replacing) {
      if (Link* link = route.target->active_suppressor()) {
        if (Trace::enabled()) {
          Trace::line("suppress " + route.target->name() + " <- " + name_ + " #" + std::to_string(sequence) +
                      " by " + link->name());
        }
        continue;
      }
    }
    route.target->deliver(data, &name_, sequence, wave, route.replacing);
  }
}

}  // namespace rsaml
