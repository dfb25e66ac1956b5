/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The trace's way to standard output, shared by the C++ runtime and the ROS 2 nodes (docs/timing.md,
// "The trace"): a thread that traces, a real-time release included, only stamps its line and appends
// it to a bounded queue, under a lock held for that alone (with priority inheritance where POSIX
// threads offer it); a writer thread of the default priority writes the queue out. A slow or full
// pipe then stalls the writer only, never a release or a thread that waits for a lock a release
// holds. A line that finds the queue full is dropped and counted, and the writer says how many in a
// line of its own; flush() waits until every line queued so far is written. Internal linkage, so
// that two generated libraries in one process (ROS 2 components) never mix their copies: each
// runtime keeps one TraceQueue, in one source file.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "rsaml/realtime.hpp"

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#include <sched.h>
#include <unistd.h>
#else
#include <condition_variable>
#include <mutex>
#endif

namespace rsaml_trace {
namespace {

/** How many lines the queue holds: about 4 s of a busy program's trace, 8 s of stalled output at 1 000 lines a second. */
constexpr std::size_t QUEUE_LINES = 8192;

class TraceQueue {
 public:
  TraceQueue() {
    lines_.resize(QUEUE_LINES);
#if defined(__unix__) || defined(__APPLE__)
    rsaml_realtime::init_inheriting_mutex(&mutex_, false);  // where priority inheritance is refused, a plain mutex
    pthread_cond_init(&wake_, nullptr);
    pthread_cond_init(&written_, nullptr);
#endif
    writer_ = std::thread([this] { write_out(); });
  }

  /** Writes out every line queued, then stops the writer. */
  ~TraceQueue() {
    lock();
    stopping_ = true;
    unlock();
    notify(wake_);
    writer_.join();
#if defined(__unix__) || defined(__APPLE__)
    pthread_cond_destroy(&written_);
    pthread_cond_destroy(&wake_);
    pthread_mutex_destroy(&mutex_);
#endif
  }

  TraceQueue(const TraceQueue&) = delete;
  TraceQueue& operator=(const TraceQueue&) = delete;

  /** The instant the stamps count from ("[  12.345 ms]": ms since then). */
  void start_at(std::chrono::steady_clock::time_point start) {
    start_ns_.store(std::chrono::duration_cast<std::chrono::nanoseconds>(start.time_since_epoch()).count(), std::memory_order_relaxed);
  }

  /**
   * Queues "[  12.345 ms] text", stamped now, without waiting: no I/O, the queue's lock held only to append it. A line
   * that finds the queue full is dropped and counted (the writer says so). For any thread, a real-time one included.
   */
  void post(const std::string& text) { append(text, false); }

  /**
   * As post(), but waits for room rather than drop the line: for the lines a run closes with (its summary), written by
   * a thread that holds no lock a real-time thread needs.
   */
  void post_waiting(const std::string& text) { append(text, true); }

  /** Waits until every line queued so far, and what was dropped before them, is written and flushed. */
  void flush() {
    lock();
    const std::uint64_t queued = queued_;
    const std::uint64_t dropped = dropped_;
    while (written_count_ < queued || said_dropped_ < dropped) {
      wait(written_);
    }
    unlock();
  }

  /**
   * For a run's summary: when lines were dropped so far, queues (waiting for room) the line that says how many,
   * "trace dropped N lines in all ...", which a reader of the summary cannot miss; none when none was.
   */
  void post_dropped_in_all() {
    lock();
    const std::uint64_t dropped = dropped_;
    unlock();
    if (dropped > 0) {
      post_waiting("trace dropped " + std::to_string(dropped) + " lines in all: its queue was full, standard output not read in"
                   " time; the trace lacks them, miss and overrun lines perhaps among them");
    }
  }

 private:
  void append(const std::string& text, bool waiting) {
    lock();
    while (waiting && count_ >= QUEUE_LINES) {
      wait(written_);
    }
    // stamped under the lock: the queue's order is the stamps' order
    const auto now = std::chrono::steady_clock::now();
    char stamp[40];
    const int stamp_length = std::snprintf(stamp, sizeof stamp, "[%10.3f ms] ", since_start(now));
    const bool was_empty = count_ == 0 && dropped_ == said_dropped_;  // else the writer is awake, or woken already
    if (count_ < QUEUE_LINES) {
      // into a slot's own storage, which the writer hands back unfreed: no memory allocated (nor freed by the writer,
      // whose allocator's locks the caller would then share) once the slot has held a line as long
      std::string& slot = lines_[count_++];
      slot.assign(stamp, static_cast<std::size_t>(stamp_length > 0 ? stamp_length : 0));
      slot.append(text);
      ++queued_;
    } else {
      ++dropped_;
      last_drop_ = now;
    }
    unlock();
    if (was_empty) {
      notify(wake_);
    }
  }

  double since_start(std::chrono::steady_clock::time_point at) const {
    return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(at.time_since_epoch()).count() -
                               start_ns_.load(std::memory_order_relaxed)) /
           1e6;
  }

  /** The writer: at the default priority, on every CPU the process may use, whatever thread made the queue. */
  void write_out() {
#if defined(__linux__)
    sched_param param{};
    pthread_setschedparam(pthread_self(), SCHED_OTHER, &param);
    cpu_set_t all;
    if (sched_getaffinity(getpid(), sizeof all, &all) == 0) {
      pthread_setaffinity_np(pthread_self(), sizeof all, &all);
    }
#endif
    std::vector<std::string> batch(QUEUE_LINES);
    for (;;) {
      lock();
      while (count_ == 0 && dropped_ == said_dropped_ && !stopping_) {
        wait(wake_);
      }
      const bool last = stopping_;
      batch.swap(lines_);
      const std::size_t count = count_;
      count_ = 0;
      // Dropped while the queue was full, so after every line of the batch and before any line queued from now on.
      const std::uint64_t dropped = dropped_;
      const std::uint64_t unsaid = dropped - said_dropped_;
      const double dropped_at = since_start(last_drop_);
      unlock();
      notify(written_);  // room for a waiting post
#if defined(__unix__) || defined(__APPLE__)
      flockfile(stdout);  // whole lines, among the other writers of the process's standard output
#endif
      for (std::size_t i = 0; i < count; ++i) {
        std::fputs(batch[i].c_str(), stdout);
        std::fputc('\n', stdout);
      }
      if (unsaid > 0) {
        std::fprintf(stdout,
                     "[%10.3f ms] trace dropped %llu lines: its queue of %zu lines was full, standard output not read in time"
                     " (%llu in all)\n",
                     dropped_at, static_cast<unsigned long long>(unsaid), QUEUE_LINES, static_cast<unsigned long long>(dropped));
      }
      std::fflush(stdout);
#if defined(__unix__) || defined(__APPLE__)
      funlockfile(stdout);
#endif
      lock();
      written_count_ += count;
      said_dropped_ = dropped;
      const bool done = last && count_ == 0 && dropped_ == said_dropped_;
      unlock();
      notify(written_);
      if (done) {
        return;
      }
    }
  }

#if defined(__unix__) || defined(__APPLE__)
  void lock() { pthread_mutex_lock(&mutex_); }
  void unlock() { pthread_mutex_unlock(&mutex_); }
  void wait(pthread_cond_t& c) { pthread_cond_wait(&c, &mutex_); }
  void notify(pthread_cond_t& c) { pthread_cond_broadcast(&c); }
  pthread_mutex_t mutex_;
  pthread_cond_t wake_;     // lines queued for the writer, or its stop
  pthread_cond_t written_;  // lines written (room in the queue, a flush answered)
#else
  void lock() { mutex_.lock(); }
  void unlock() { mutex_.unlock(); }
  void wait(std::condition_variable_any& c) { c.wait(mutex_); }
  void notify(std::condition_variable_any& c) { c.notify_all(); }
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::condition_variable_any written_;
#endif
  std::atomic<std::int64_t> start_ns_{
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count()};
  std::vector<std::string> lines_;  // QUEUE_LINES slots, the first count_ of them queued
  std::size_t count_ = 0;
  std::chrono::steady_clock::time_point last_drop_;  // the last line dropped
  std::uint64_t queued_ = 0;         // lines queued since the start
  std::uint64_t written_count_ = 0;  // of them, written and flushed
  std::uint64_t dropped_ = 0;        // lines dropped, the queue full
  std::uint64_t said_dropped_ = 0;   // of them, said by a line of the writer
  bool stopping_ = false;
  std::thread writer_;  // last: started once everything above is made
};

}  // namespace
}  // namespace rsaml_trace
