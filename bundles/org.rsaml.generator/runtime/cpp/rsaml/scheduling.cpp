/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Where and how each thread runs: cores claimed by processors, real-time priorities, and
// SCHED_DEADLINE for the releases of an EDF processor (docs/timing.md, "EDF").
#include <algorithm>
#include <csignal>
#include <set>
#include <string>

#include "rsaml/internal.hpp"
#include "rsaml/realtime.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#include <sched.h>
#define RSAML_HAS_PTHREAD 1
#endif
#if defined(__linux__)
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace rsaml {

using internal::millis;

namespace {

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
    // EDF: SCHED_DEADLINE, asked for at the first release (become_deadline), so that the kernel's periods are the
    // release's. The kernel admits a deadline thread only where it may run on every CPU of its root domain, so one
    // pinned to its processor's core is unpinned first. Until then the thread waits at its rank.
#if defined(__linux__)
    if (r.module->core() >= 0 && !all_cores_.empty()) {
      cpu_set_t set;
      CPU_ZERO(&set);
      for (int cpu : all_cores_) {
        CPU_SET(cpu, &set);
      }
      pthread_setaffinity_np(self, sizeof(set), &set);
      r.unpinned = " on cores " + core_list(all_cores_) + ", not core " + std::to_string(r.module->cpu()) +
                   " alone (the kernel admits a deadline thread only on all CPUs of its root domain)";
    }
#endif
    r.sched = apply_priority(self, Policy::Fifo, r.rank) ? "SCHED_FIFO rank " + std::to_string(r.rank) : std::string("default");
    r.deadline_wanted = true;
    return;  // said at the first release
  } else if (apply_priority(self, r.policy, r.rank)) {
    r.sched = std::string(r.policy == Policy::RoundRobin ? "SCHED_RR" : "SCHED_FIFO") + " rank " + std::to_string(r.rank);
  } else {
    r.sched = "default";
  }
  Trace::line("sched " + r.label + " " + r.sched);
}

namespace {

// The kernel's SIGXCPU for a deadline thread whose runtime ran out (SCHED_FLAG_DL_OVERRUN), counted on the thread
// that takes it: only deadline threads leave it unblocked.
thread_local volatile std::sig_atomic_t overruns_signalled = 0;

#if defined(__linux__)
void on_overrun(int) { overruns_signalled = overruns_signalled + 1; }
#endif

}  // namespace

unsigned long internal::deadline_overruns() { return static_cast<unsigned long>(overruns_signalled); }

void internal::count_deadline_overruns() {
#if defined(__linux__)
  struct sigaction action {};
  action.sa_handler = on_overrun;
  action.sa_flags = SA_RESTART;  // a system call the signal interrupts goes on where the kernel can restart it
  sigemptyset(&action.sa_mask);
  sigaction(SIGXCPU, &action, nullptr);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGXCPU);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
#endif
}

bool System::become_deadline(Release& r, Clock::time_point release_at) {
  // SCHED_DEADLINE with runtime = modeled cost, deadline and period as modeled, asked for now: a thread that never was
  // a deadline thread gets its first period from this moment, and ending each job with sched_yield() keeps the
  // kernel's later periods on this grid. Reclaiming (SCHED_FLAG_RECLAIM) lets a job run past its runtime on
  // bandwidth no deadline thread reserved, so that time the platform takes while charging the job (the hypervisor,
  // interrupts) does not throttle it to its next period; the kernel signals a runtime that ran out all the same.
  const Clock::time_point asked = Clock::now();
  const std::int64_t cost = r.bounds.cost.count();
  const std::int64_t deadline = r.bounds.deadline.count();
  const std::int64_t period = r.period.count();
  std::string refused = rsaml_realtime::request_deadline(cost, deadline, period, rsaml_realtime::kFlagReclaim | rsaml_realtime::kFlagOverrun);
  std::string how = ", reclaiming";
  if (!refused.empty()) {
    const std::string with_flags = refused;
    refused = rsaml_realtime::request_deadline(cost, deadline, period);
    how = " (without reclaiming: " + with_flags + ")";
  }
  const std::string fallback = r.sched;
  if (refused.empty()) {
#if defined(__linux__)
    r.tid = static_cast<long>(syscall(SYS_gettid));
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGXCPU);
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
#endif
    r.sched = "SCHED_DEADLINE runtime " + millis(r.bounds.cost) + " deadline " + millis(r.bounds.deadline) + " period " +
              millis(r.period) + how + ", its periods from its first release (asked " +
              millis(std::chrono::duration_cast<Nanos>(asked - release_at)) + " after it)" + r.unpinned +
              " (kernel: " + rsaml_realtime::kernel_policy() + ")";
  } else {
#if defined(__linux__)
    if (!r.unpinned.empty() && r.module->cpu() < CPU_SETSIZE) {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(r.module->cpu(), &set);
      pthread_setaffinity_np(pthread_self(), sizeof(set), &set);  // back on its core, as traced
    }
#endif
    r.sched = fallback + " instead of EDF: " + refused;
  }
  Trace::line("sched " + r.label + " " + r.sched);
  return refused.empty();
}

void System::let_deadline_threads_go() {
#if defined(__linux__)
  for (auto& release : releases_) {
    // stopping_ is set: a thread seen waiting here starts no job when it resumes (run_release)
    // yielding first: its store follows the thread's write of tid, so tid is read only once it is written
    if (release->yielding.load() && release->tid != 0) {
      sched_param param{};
      sched_setscheduler(static_cast<pid_t>(release->tid), SCHED_OTHER, &param);
    }
  }
#endif
}

std::string System::schedule_worker(const std::string& module, bool unbounded) {
#ifdef RSAML_HAS_PTHREAD
  const std::thread::native_handle_type self = pthread_self();
#else
  const std::thread::native_handle_type self{};
#endif
  if (unbounded) {
    // Aperiodic reactions, which the analysis excludes: at the default priority, below every real-time thread, so
    // that more data than the module can react to takes no real-time time from the releases (the thread is made
    // SCHED_OTHER whatever the thread that started it ran at; lowering a thread's priority is always permitted).
#ifdef RSAML_HAS_PTHREAD
    sched_param param{};
    pthread_setschedparam(self, SCHED_OTHER, &param);
#endif
    Trace::line("sched " + module + " worker default: it serves aperiodic reactions, whose load the model does not bound,"
                " below every real-time thread");
    return "default (aperiodic reactions)";
  }
  // Priority 0 of the analysis: the lowest real-time priority, below every release (rank 1 and up).
  const std::string sched = options_.realtime && apply_priority(self, Policy::Fifo, 0) ? "SCHED_FIFO rank 0" : "default";
  Trace::line("sched " + module + " worker " + sched);
  return sched;
}

}  // namespace rsaml
