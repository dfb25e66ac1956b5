/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Where and how each thread runs: cores claimed by processors, real-time priorities, and
// SCHED_DEADLINE for the releases of an EDF processor.
#include <algorithm>
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

}  // namespace rsaml
