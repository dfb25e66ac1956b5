/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
#include "rsaml/runtime.hpp"
#include "rsaml/realtime.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#include <sched.h>
#define RSAML_HAS_PTHREAD 1
#endif

namespace rsaml {

namespace {

std::mutex trace_mutex;
std::atomic<bool> trace_enabled{true};
Clock::time_point trace_start = Clock::now();
thread_local Activation* current_activation = nullptr;
volatile std::sig_atomic_t interrupted = 0;

void on_signal(int) { interrupted = 1; }

// The longest run the clock arithmetic can hold without overflow: 2^60 ns (about 36 years), as
// the generator's limit for modeled times.
constexpr long long kMaxRunMs = (1LL << 60) / 1000000;

void usage(std::FILE* out, const char* program) {
  std::fprintf(out,
               "Usage: %s [--run-for-ms N] [--quiet] [--no-realtime] [--busy-work PERCENT]\n"
               "  --run-for-ms N        stop after N milliseconds (default: run until interrupted)\n"
               "  --quiet               no trace of releases and data flow (misses, overruns and the\n"
               "                        summary are still reported)\n"
               "  --no-realtime         do not ask for real-time priorities\n"
               "  --busy-work PERCENT   each timed job first consumes PERCENT %% of its modeled execution\n"
               "                        time on the CPU, standing in for user code (100: as modeled)\n",
               program);
}

/** Real-time priority for a release thread where the platform allows it; false when not permitted. */
bool apply_priority(std::thread::native_handle_type thread, Policy policy, int rank) {
#ifdef RSAML_HAS_PTHREAD
  const int posix = policy == Policy::RoundRobin ? SCHED_RR : SCHED_FIFO;
  const int low = sched_get_priority_min(posix);
  const int high = sched_get_priority_max(posix);
  if (low < 0 || high < low) {
    return false;
  }
  sched_param param{};
  param.sched_priority = std::min(low + rank, high);
  return pthread_setschedparam(thread, posix, &param) == 0;
#else
  (void)thread;
  (void)policy;
  (void)rank;
  return false;
#endif
}

/** The calling thread's CPU time. */
Nanos thread_cpu_time() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec t{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0) {
    return Nanos(static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec);
  }
#endif
  return std::chrono::duration_cast<Nanos>(Clock::now().time_since_epoch());
}

/** Consumes CPU time on the calling thread: busy work standing in for user code. */
void consume(Nanos amount) {
  const Nanos until = thread_cpu_time() + amount;
  while (thread_cpu_time() < until) {
  }
}

std::string millis(Nanos t) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ms", static_cast<double>(t.count()) / 1e6);
  return text;
}


#if defined(__linux__)
/** Cores as a short list: 0-3,6. */
std::string core_list(const std::vector<int>& cores) {
  std::string out;
  for (std::size_t i = 0; i < cores.size();) {
    std::size_t j = i;
    while (j + 1 < cores.size() && cores[j + 1] == cores[j] + 1) {
      ++j;
    }
    out += (out.empty() ? "" : ",") + std::to_string(cores[i]) + (j > i ? "-" + std::to_string(cores[j]) : "");
    i = j + 1;
  }
  return out;
}
#endif

}  // namespace

Options parse_options(int argc, char** argv, const char* program) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--run-for-ms" && i + 1 < argc) {
      char* end = nullptr;
      errno = 0;
      const long long value = std::strtoll(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || errno == ERANGE || value < 0 || value > kMaxRunMs) {
        std::fprintf(stderr, "%s: --run-for-ms needs a number of milliseconds from 0 to %lld, not '%s'\n", program, kMaxRunMs,
                     argv[i]);
        options.exit = true;
        options.status = 2;
        return options;
      }
      options.run_for_ms = value;
    } else if (arg == "--quiet") {
      options.trace = false;
    } else if (arg == "--no-realtime") {
      options.realtime = false;
    } else if (arg == "--busy-work" && i + 1 < argc) {
      char* end = nullptr;
      errno = 0;
      const long long value = std::strtoll(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || errno == ERANGE || value < 0 || value > 1000) {
        std::fprintf(stderr, "%s: --busy-work needs a percentage of the modeled execution time from 0 to 1000, not '%s'\n",
                     program, argv[i]);
        options.exit = true;
        options.status = 2;
        return options;
      }
      options.busy_work_percent = value;
    } else if (arg == "--help" || arg == "-h") {
      usage(stdout, program);
      options.exit = true;
      return options;
    } else {
      std::fprintf(stderr, "%s: unknown argument '%s'\n", program, arg.c_str());
      usage(stderr, program);
      options.exit = true;
      options.status = 2;
      return options;
    }
  }
  return options;
}

void Trace::configure(bool enabled, Clock::time_point start) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  trace_enabled = enabled;
  trace_start = start;
}

bool Trace::enabled() { return trace_enabled; }

void Trace::line(const std::string& text) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  if (!trace_enabled) {
    return;
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - trace_start).count();
  std::fprintf(stdout, "[%10.3f ms] %s\n", ms, text.c_str());
}

void Trace::report(const std::string& text) {
  std::lock_guard<std::mutex> lock(trace_mutex);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - trace_start).count();
  std::fprintf(stdout, "[%10.3f ms] %s\n", ms, text.c_str());
}

void Trace::flush() {
  std::lock_guard<std::mutex> lock(trace_mutex);
  std::fflush(stdout);
}

Link::Link(std::string name, Nanos duration)
    : name_(std::move(name)), duration_(duration), until_(std::numeric_limits<Clock::rep>::min()) {}

void Link::trigger() { until_.store((Clock::now() + duration_).time_since_epoch().count()); }

bool Link::active() const { return Clock::now().time_since_epoch().count() < until_.load(); }

Activation::Activation(Module& module, std::uint64_t wave, bool timed, Clock::time_point release)
    : module(module), wave(wave), timed(timed), release(release), lock(module.mutex_), previous_(current_activation) {
  current_activation = this;
  if (module.depth_++ == 0) {
    for (auto& latch : module.latches_) {
      latch();
    }
  }
}

Activation::~Activation() {
  --module.depth_;
  current_activation = previous_;
}

Activation* Activation::current() { return current_activation; }

Module::Module(System& system, std::string name, int core, std::string host, int cpu)
    : system_(system), name_(std::move(name)), core_(core), host_(std::move(host)), cpu_(cpu >= 0 ? cpu : core) {}

Module::~Module() { stop_worker(); }

void Module::post(std::uint64_t wave, std::function<void()> work) {
  {
    std::lock_guard<std::mutex> lock(mail_mutex_);
    if (stopping_) {
      return;
    }
    mail_.push_back(Mail{wave, Clock::now(), std::move(work)});
  }
  mail_cv_.notify_one();
}

void Module::start_worker() {
  if (!worker_.joinable()) {
    worker_ = std::thread([this] { run_worker(); });
    system_.place(worker_.native_handle(), name_, *this);
  }
}

void Module::stop_worker() {
  {
    std::lock_guard<std::mutex> lock(mail_mutex_);
    stopping_ = true;
  }
  mail_cv_.notify_all();
  if (worker_.joinable()) {
    worker_.join();
  }
}

void Module::run_worker() {
  const std::string sched = system_.schedule_worker(name_);
  if (reactions_) {
    reactions_->sched = sched;
  }
  for (;;) {
    Mail mail;
    {
      std::unique_lock<std::mutex> lock(mail_mutex_);
      mail_cv_.wait(lock, [this] { return stopping_ || !mail_.empty(); });
      if (stopping_) {
        return;
      }
      mail = std::move(mail_.front());
      mail_.pop_front();
    }
    // A reaction's job is released by the arrival of the data that starts it.
    Activation activation(*this, mail.wave, false, mail.arrived);
    mail.work();
  }
}

void Module::start_step(std::uint64_t wave) {
  Activation activation(*this, wave, false, Clock::now());
  waves_.insert(wave);
  trace("start " + name_);
  on_start();
  publish_outputs();
}

void Module::timed_release(const std::string& label, Clock::time_point release, const std::function<void()>& body,
                           Nanos busy) {
  Activation activation(*this, system_.new_wave(), true, release);
  waves_.insert(activation.wave);
  trace("release " + label);
  if (busy.count() > 0) {
    consume(busy);
  }
  body();
}

void Module::run_action(const char* label, Nanos offset, const std::function<void()>& body) {
  Activation* activation = Activation::current();
  if (activation && activation->timed && offset.count() > 0) {
    // Other activations of this module may run while this one waits for the action's start date.
    activation->lock.unlock();
    const bool go_on = system_.sleep_until(activation->release + offset);
    activation->lock.lock();
    if (!go_on) {
      return;
    }
  }
  trace("action " + name_ + "." + label);
  body();
}

bool Module::begin_reaction(Nanos min_interval) {
  Activation* activation = Activation::current();
  if (activation) {
    if (!waves_.insert(activation->wave).second) {
      return false;
    }
    while (waves_.size() > 1024) {
      waves_.erase(waves_.begin());
    }
  }
  // Arrivals, not the worker's start times, are at least min_interval apart: the sporadic task the
  // analysis assumes, released by the arrivals.
  const Clock::time_point arrived = activation ? activation->release : Clock::now();
  if (min_interval.count() > 0 && reacted_ && arrived - last_reaction_ < min_interval) {
    return false;
  }
  reacted_ = true;
  last_reaction_ = arrived;
  trace("react " + name_);
  return true;
}

void Module::measure_reactions(std::string label, JobBounds bounds) {
  reactions_ = &system_.reactions(*this, std::move(label), bounds);
}

void Module::react(Nanos min_interval, const std::function<void()>& body) {
  if (!begin_reaction(min_interval)) {
    return;
  }
  Activation* activation = Activation::current();
  const Clock::time_point arrived = activation ? activation->release : Clock::now();
  const Clock::time_point started = Clock::now();
  const Nanos cpu = thread_cpu_time();
  if (reactions_) {
    const Nanos busy = system_.busy_work(reactions_->bounds.cost);
    if (busy.count() > 0) {
      consume(busy);
    }
  }
  body();
  if (reactions_) {
    system_.reaction_done(*reactions_, arrived, started, Clock::now(), thread_cpu_time() - cpu);
  }
}

bool Module::due(Clock::time_point& last, Nanos min_interval) {
  const Clock::time_point now = Clock::now();
  if (last != Clock::time_point{} && now - last < min_interval) {
    return false;
  }
  last = now;
  return true;
}

void Module::trace(const std::string& text) const {
  if (Trace::enabled()) {
    Trace::line(text);
  }
}

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
  releases_.push_back(std::unique_ptr<Release>(new Release{&module, std::move(label), period, offset, policy, rank, bounds,
                                                           std::move(body), std::thread(), std::string(), JobStats()}));
}

bool System::sleep_until(Clock::time_point t) {
  // No lock shared with other threads: a real-time thread must not wait for one that holds it
  // while preempted. The stop is seen within a slice.
  constexpr Nanos kSlice = std::chrono::milliseconds(20);
  for (;;) {
    if (stopping_.load()) {
      return false;
    }
    const Clock::time_point now = Clock::now();
    if (now >= t) {
      return true;
    }
    const Clock::time_point until = t - now > kSlice ? now + kSlice : t;
#if defined(__linux__)
    // steady_clock is CLOCK_MONOTONIC: sleep to the absolute time, with no drift.
    const long long ns = std::chrono::duration_cast<Nanos>(until.time_since_epoch()).count();
    timespec at{};
    at.tv_sec = static_cast<time_t>(ns / 1000000000LL);
    at.tv_nsec = static_cast<long>(ns % 1000000000LL);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &at, nullptr);
#else
    std::this_thread::sleep_until(until);
#endif
  }
}

void System::claim_cores() {
#if defined(__linux__)
  cpu_set_t claimed;
  CPU_ZERO(&claimed);
  std::set<std::string> coreless;  // the hosts of the modules without a core
  for (Module* module : modules_) {
    if (module->core() < 0) {
      coreless.insert(module->host().empty() ? "main" : module->host());
    } else if (module->cpu() < CPU_SETSIZE) {
      CPU_SET(module->cpu(), &claimed);
      cores_claimed_ = true;
    }
  }
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) == 0) {
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
      if (CPU_ISSET(cpu, &allowed)) {
        all_cores_.push_back(cpu);
        if (cores_claimed_ && !CPU_ISSET(cpu, &claimed)) {
          unclaimed_cores_.push_back(cpu);
        }
      }
    }
  }
  if (coreless.size() > 1) {
    std::string hosts;
    for (const std::string& h : coreless) {
      hosts += (hosts.empty() ? "" : ", ") + h;
    }
    Trace::report("cpu the modules without a core of hosts " + hosts + " share the cores no processor claims on this machine, while" +
                  " the analysis counts each host's apart: their bounds do not hold in this run (give their processors cores)");
  }
#endif
}

void System::place(std::thread::native_handle_type thread, const std::string& label, const Module& module) {
  const int core = module.core();
  // Another host's core on a CPU of its own: one program runs every host (the generator's choice, docs/timing.md).
  const std::string where = "core " + std::to_string(core) +
                            (module.cpu() == core ? std::string()
                                                  : " of host " + module.host() + " on CPU " + std::to_string(module.cpu()) +
                                                        " (one program runs every host: each host's cores on CPUs of their own)");
#if defined(__linux__)
  if (core >= 0) {
    const int cpu = module.cpu();
    if (cpu < CPU_SETSIZE) {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(cpu, &set);
      if (pthread_setaffinity_np(thread, sizeof(set), &set) == 0) {
        Trace::line("cpu " + label + " " + where);
        return;
      }
    }
    Trace::line("cpu " + label + " " + where + " not available: default");
    return;
  }
  if (!cores_claimed_) {
    return;  // no processor claims a core: every thread where the OS puts it
  }
  if (!unclaimed_cores_.empty()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    for (int cpu : unclaimed_cores_) {
      CPU_SET(cpu, &set);
    }
    if (pthread_setaffinity_np(thread, sizeof(set), &set) == 0) {
      Trace::line("cpu " + label + " cores " + core_list(unclaimed_cores_) + " unclaimed");
      return;
    }
  }
  Trace::line("cpu " + label + " no unclaimed core: default");
#else
  (void)thread;
  if (core >= 0) {
    Trace::line("cpu " + label + " " + where + " not supported on this platform: default");
  }
#endif
}

void System::schedule_self(Release& r) {
#ifdef RSAML_HAS_PTHREAD
  const std::thread::native_handle_type self = pthread_self();
#else
  const std::thread::native_handle_type self{};
#endif
  place(self, r.label, *r.module);
  if (!options_.realtime) {
    r.sched = "default";
  } else if (r.policy == Policy::Deadline) {
    // EDF: SCHED_DEADLINE with runtime = modeled cost, deadline and period as modeled. The kernel
    // admits a deadline thread only where it may run on every CPU of its root domain, so one pinned
    // to its processor's core is unpinned first.
    std::string refused;
    std::string where;
#if defined(__linux__)
    if (r.module->core() >= 0 && !all_cores_.empty()) {
      cpu_set_t set;
      CPU_ZERO(&set);
      for (int cpu : all_cores_) {
        CPU_SET(cpu, &set);
      }
      pthread_setaffinity_np(self, sizeof(set), &set);
      where = " on cores " + core_list(all_cores_) + ", not core " + std::to_string(r.module->cpu()) +
              " alone (the kernel admits a deadline thread only on all CPUs of its root domain)";
    }
#endif
    refused = rsaml_realtime::request_deadline(r.bounds.cost.count(), r.bounds.deadline.count(), r.period.count());
    if (refused.empty()) {
      r.sched = "SCHED_DEADLINE runtime " + millis(r.bounds.cost) + " deadline " + millis(r.bounds.deadline) + " period " +
                millis(r.period) + where + " (kernel: " + rsaml_realtime::kernel_policy() + ")";
    }
#if defined(__linux__)
    if (!refused.empty() && !where.empty() && r.module->cpu() < CPU_SETSIZE) {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(r.module->cpu(), &set);
      pthread_setaffinity_np(self, sizeof(set), &set);  // back on its core, as traced
    }
#endif
    if (r.sched.empty()) {
      r.sched = (apply_priority(self, Policy::Fifo, r.rank) ? "SCHED_FIFO rank " + std::to_string(r.rank) : std::string("default")) +
                " instead of EDF: " + refused;
    }
  } else if (apply_priority(self, r.policy, r.rank)) {
    r.sched = std::string(r.policy == Policy::RoundRobin ? "SCHED_RR" : "SCHED_FIFO") + " rank " + std::to_string(r.rank);
  } else {
    r.sched = "default";
  }
  Trace::line("sched " + r.label + " " + r.sched);
}

std::string System::schedule_worker(const std::string& module) {
#ifdef RSAML_HAS_PTHREAD
  const std::thread::native_handle_type self = pthread_self();
#else
  const std::thread::native_handle_type self{};
#endif
  // Priority 0 of the analysis: the lowest real-time priority, below every release (rank 1 and up).
  const std::string sched = options_.realtime && apply_priority(self, Policy::Fifo, 0) ? "SCHED_FIFO rank 0" : "default";
  Trace::line("sched " + module + " worker " + sched);
  return sched;
}

Reactions& System::reactions(Module& module, std::string label, JobBounds bounds) {
  reactions_.push_back(std::unique_ptr<Reactions>(new Reactions{&module, std::move(label), bounds, std::string(), JobStats()}));
  return *reactions_.back();
}

Nanos System::busy_work(Nanos cost) const {
  // The busy work stops short of the modeled time by 5 % (at most 100 us), which the job's own
  // bookkeeping (trace, sends, the lock) takes instead.
  if (options_.busy_work_percent <= 0) {
    return Nanos(0);
  }
  return cost * options_.busy_work_percent / 100 - std::min(cost / 20, Nanos(100000));
}

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
  // Releases stay on the grid epoch + offset + k * period, however long one of them takes.
  while (sleep_until(next)) {
    const Clock::time_point started = Clock::now();
    const Nanos cpu = thread_cpu_time();
    release.stats.worst_start_latency =
        std::max(release.stats.worst_start_latency, std::chrono::duration_cast<Nanos>(started - next));
    release.module->timed_release(release.label, next, release.body, busy);
    const Nanos used = thread_cpu_time() - cpu;
    job_done(release, next, Clock::now(), used);
    next += release.period;
  }
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
