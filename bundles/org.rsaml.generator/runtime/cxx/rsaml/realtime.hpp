/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// EDF for the releases of an EDF processor: Linux's SCHED_DEADLINE, and the locks with priority
// inheritance (a module's, a node's, the trace queue's), shared by the C++ runtime and the ROS 2 nodes (docs/timing.md, "EDF", "Module
// lock"). The SCHED_DEADLINE calls have internal linkage, so that two generated libraries in one process (ROS 2
// components) never mix their copies; the lock class, InheritingLock, is a member of classes of external linkage (a C++
// module, a ROS 2 node's schedule) and so has external linkage too, as they do: its functions are inline, the same in
// every library one RsaML generates.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <string>

#if !defined(__unix__) && !defined(__APPLE__)
#include <condition_variable>
#include <mutex>
#endif

#if defined(__linux__)
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif
#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#endif

namespace rsaml_realtime {
namespace {

#if defined(__linux__)
// sched_setattr and sched_getattr as system calls: glibc has no wrapper before 2.41.
constexpr unsigned kSchedDeadline = 6;
#endif
/** SCHED_FLAG_RECLAIM: a deadline thread may run past its runtime on bandwidth no deadline thread reserved (GRUB). */
constexpr std::uint64_t kFlagReclaim = 0x02;
/** SCHED_FLAG_DL_OVERRUN: the kernel sends SIGXCPU to a deadline thread whose runtime ran out. */
constexpr std::uint64_t kFlagOverrun = 0x04;
#if defined(__linux__)
struct SchedAttr {
  std::uint32_t size;
  std::uint32_t sched_policy;
  std::uint64_t sched_flags;
  std::int32_t sched_nice;
  std::uint32_t sched_priority;
  std::uint64_t sched_runtime;
  std::uint64_t sched_deadline;
  std::uint64_t sched_period;
};
#endif

inline std::string kernel_ms(std::uint64_t ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f ms", static_cast<double>(ns) / 1e6);
  return text;
}

/**
 * The calling thread's policy as the kernel reports it (sched_getattr), with the runtime, deadline
 * and period it holds for a SCHED_DEADLINE thread, and its flags reclaim and dl-overrun where set.
 */
inline std::string kernel_policy() {
#if defined(__linux__)
  SchedAttr attr{};
  if (syscall(SYS_sched_getattr, 0, &attr, sizeof attr, 0) != 0) {
    return std::string("unknown (") + std::strerror(errno) + ")";
  }
  switch (attr.sched_policy) {
    case SCHED_OTHER: return "SCHED_OTHER";
    case SCHED_FIFO: return "SCHED_FIFO";
    case SCHED_RR: return "SCHED_RR";
    case kSchedDeadline:
      return "SCHED_DEADLINE runtime " + kernel_ms(attr.sched_runtime) + " deadline " + kernel_ms(attr.sched_deadline) + " period " +
             kernel_ms(attr.sched_period) + ((attr.sched_flags & kFlagReclaim) != 0 ? " reclaim" : "") +
             ((attr.sched_flags & kFlagOverrun) != 0 ? " dl-overrun" : "");
    default: return "policy " + std::to_string(attr.sched_policy);
  }
#else
  return "unknown";
#endif
}

/**
 * Puts the calling thread under SCHED_DEADLINE with runtime = the modeled execution time, and the
 * modeled deadline and period (nanoseconds), with the kernel's `flags` (kFlagReclaim, kFlagOverrun).
 * Returns why not when it cannot ("" when granted). The kernel admits a deadline thread only where it
 * may run on every CPU of its root domain: the caller unpins the thread first. The kernel's first
 * period begins now when the thread was never a deadline thread (or its last deadline has passed).
 */
inline std::string request_deadline(std::int64_t runtime, std::int64_t deadline, std::int64_t period, std::uint64_t flags = 0) {
#if defined(__linux__)
  if (runtime < 1024) {
    return "the model gives it no execution time (SCHED_DEADLINE needs a runtime of 1 us or more)";
  }
  if (runtime > deadline || deadline > period) {
    return "SCHED_DEADLINE needs execution time <= deadline <= period";
  }
  SchedAttr attr{};
  attr.size = sizeof attr;
  attr.sched_policy = kSchedDeadline;
  attr.sched_runtime = static_cast<std::uint64_t>(runtime);
  attr.sched_deadline = static_cast<std::uint64_t>(deadline);
  attr.sched_period = static_cast<std::uint64_t>(period);
  attr.sched_flags = flags;
  if (syscall(SYS_sched_setattr, 0, &attr, 0) != 0) {
    return std::string("the kernel refused SCHED_DEADLINE: ") + std::strerror(errno);
  }
  return "";
#else
  (void)runtime;
  (void)deadline;
  (void)period;
  (void)flags;
  return "SCHED_DEADLINE is Linux's";
#endif
}

}  // namespace
}  // namespace rsaml_realtime

namespace rsaml_realtime {

#if defined(__unix__) || defined(__APPLE__)
/**
 * Initialises a lock the real-time threads share with others (a module's, a node's, the trace queue's): a mutex
 * with priority inheritance (PTHREAD_PRIO_INHERIT), so that a thread holding it runs at the priority of the
 * highest thread waiting for it, and a release at its real-time priority waits for a thread of a lower or the
 * default priority only as long as that thread needs the lock, not while other threads run (a priority
 * inversion); recursive where its owner takes it again (a module's activations). Where the platform refuses
 * priority inheritance, a plain mutex. Returns "PTHREAD_PRIO_INHERIT", or what the mutex is instead and why.
 */
inline std::string init_inheriting_mutex(pthread_mutex_t* mutex, bool recursive) {
  pthread_mutexattr_t attributes;
  pthread_mutexattr_init(&attributes);
  if (recursive) {
    pthread_mutexattr_settype(&attributes, PTHREAD_MUTEX_RECURSIVE);
  }
  const int refused = pthread_mutexattr_setprotocol(&attributes, PTHREAD_PRIO_INHERIT);
  int error = pthread_mutex_init(mutex, &attributes);
  std::string protocol = "PTHREAD_PRIO_INHERIT";
  if (refused != 0 || error != 0) {
    protocol = std::string("without priority inheritance: ") + std::strerror(refused != 0 ? refused : error);
    if (error != 0) {
      pthread_mutexattr_setprotocol(&attributes, PTHREAD_PRIO_NONE);
      error = pthread_mutex_init(mutex, &attributes);
    }
  }
  pthread_mutexattr_destroy(&attributes);
  if (error != 0) {
    std::fprintf(stderr, "rsaml: cannot create a lock: %s\n", std::strerror(error));
    std::abort();
  }
  return protocol;
}
#endif


/**
 * A lock with priority inheritance where POSIX threads offer it (init_inheriting_mutex): a thread holding it runs at the
 * priority of the highest thread waiting for it, so that a release waits for a thread of a lower or the default priority
 * only as long as that thread needs the lock, not while other threads run; and a condition, waited on under it. The one
 * lock class of both runtimes: a C++ module has two, its lock (a module is a lock group of the analysis), recursive, held
 * while any of its activations runs (docs/timing.md, "Module lock"), and its mailbox's, which the releases that send to
 * the module share with its worker for a push or a pop, the worker waiting on its condition; a ROS 2 node has two, its
 * lock (its activations') and its statistics' (rsaml/scheduling.hpp).
 */
class InheritingLock {
 public:
  /** A recursive lock may be taken again by the thread that holds it (a module's activations). */
  explicit InheritingLock(bool recursive = false)
#if defined(__unix__) || defined(__APPLE__)
      : protocol_(init_inheriting_mutex(&mutex_, recursive)) {
    pthread_cond_init(&ready_, nullptr);
  }
  ~InheritingLock() {
    pthread_cond_destroy(&ready_);
    pthread_mutex_destroy(&mutex_);
  }
  void lock() { pthread_mutex_lock(&mutex_); }
  void unlock() { pthread_mutex_unlock(&mutex_); }
  /** Waits, holding the lock (once), until notified (or woken spuriously); holds it again on return. */
  void wait() { pthread_cond_wait(&ready_, &mutex_); }
  /** Wakes one thread waiting on the condition. */
  void notify() { pthread_cond_signal(&ready_); }
#else
      : protocol_("without priority inheritance: not supported on this platform") {
    (void)recursive;  // std::recursive_mutex: recursive or not
  }
  void lock() { mutex_.lock(); }
  void unlock() { mutex_.unlock(); }
  void wait() { ready_.wait(mutex_); }
  void notify() { ready_.notify_one(); }
#endif
  InheritingLock(const InheritingLock&) = delete;
  InheritingLock& operator=(const InheritingLock&) = delete;
  /** "PTHREAD_PRIO_INHERIT", or what the lock is instead and why. */
  const std::string& protocol() const { return protocol_; }

 private:
#if defined(__unix__) || defined(__APPLE__)
  pthread_mutex_t mutex_;
  pthread_cond_t ready_;
#else
  std::recursive_mutex mutex_;
  std::condition_variable_any ready_;
#endif
  std::string protocol_;
};

}  // namespace rsaml_realtime
