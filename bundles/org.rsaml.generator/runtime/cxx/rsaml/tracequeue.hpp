/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The trace's way to standard output, shared by the C++ runtime and the ROS 2 nodes (docs/timing.md,
// "The trace"): a thread that traces, a real-time release included, only stamps its line and copies
// it into a bounded ring of bytes, under a lock held for that alone (with priority inheritance where
// POSIX threads offer it); a writer thread of the default priority writes the ring out. A slow or
// full pipe then stalls the writer only, never a release or a thread that waits for a lock a release
// holds. The ring is part of the queue (static storage, as each runtime keeps its queue): no line
// takes heap memory, and the writer frees nothing a thread that traces allocated, so that no
// real-time thread shares the allocator's locks with it (docs/timing.md, "Memory between threads").
// A line that finds the ring full is dropped and counted, and the writer says how many in a line
// of its own; flush() waits until every line queued so far is written. Internal linkage, so that
// two generated libraries in one process (ROS 2 components) never mix their copies: each runtime
// keeps one TraceQueue, in one source file, as a function's static.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

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

/** How many bytes the queue's lines take at most (1 MiB, 128 a line on average), stamps and newlines included. */
constexpr std::size_t QUEUE_BYTES = QUEUE_LINES * 128;

/** The longest line queued: a longer one is cut there (no line of the runtimes comes near). */
constexpr std::size_t LINE_BYTES = 16384;

class TraceQueue {
 public:
  TraceQueue() {
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
    const std::size_t length = text.size() < LINE_BYTES ? text.size() : LINE_BYTES;
    lock();
    bool was_empty;  // taken when the line is appended or dropped: else the writer is awake, or woken already
    for (;;) {
      // stamped under the lock: the queue's order is the stamps' order
      const auto now = std::chrono::steady_clock::now();
      char stamp[40];
      const int printed = std::snprintf(stamp, sizeof stamp, "[%10.3f ms] ", since_start(now));
      const std::size_t stamp_length = printed > 0 ? static_cast<std::size_t>(printed) : 0;
      const std::size_t need = stamp_length + length + 1;
      was_empty = lines_ == 0 && dropped_ == said_dropped_;  // after any wait below: the writer may have emptied it meanwhile
      if (lines_ < QUEUE_LINES && used_ + need <= QUEUE_BYTES) {
        // copied into the ring, behind the lines the writer may be writing out now (it owns [head_, head_ + used_))
        copy_in(stamp, stamp_length);
        copy_in(text.data(), length);
        copy_in("\n", 1);
        ++lines_;
        ++queued_;
        break;
      }
      if (!waiting) {
        ++dropped_;
        last_drop_ = now;
        break;
      }
      wait(written_);
    }
    unlock();
    if (was_empty) {
      notify(wake_);
    }
  }

  /** Appends bytes at the ring's end (the lock held, the room checked). */
  void copy_in(const char* bytes, std::size_t length) {
    const std::size_t at = static_cast<std::size_t>((head_ + used_) % QUEUE_BYTES);
    const std::size_t first = length < QUEUE_BYTES - at ? length : QUEUE_BYTES - at;
    std::memcpy(ring_ + at, bytes, first);
    std::memcpy(ring_, bytes + first, length - first);
    used_ += length;
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
    for (;;) {
      lock();
      while (lines_ == 0 && dropped_ == said_dropped_ && !stopping_) {
        wait(wake_);
      }
      const bool last = stopping_;
      // The lines queued so far, [head_, head_ + bytes): the threads that trace append behind them, never into them,
      // until they are written and handed back below.
      const std::uint64_t head = head_;
      const std::size_t bytes = used_;
      const std::size_t count = lines_;
      // Dropped while the ring was full, so after every line taken now and before any line queued from now on.
      const std::uint64_t dropped = dropped_;
      const std::uint64_t unsaid = dropped - said_dropped_;
      const double dropped_at = since_start(last_drop_);
      unlock();
#if defined(__unix__) || defined(__APPLE__)
      flockfile(stdout);  // whole lines, among the other writers of the process's standard output
#endif
      const std::size_t at = static_cast<std::size_t>(head % QUEUE_BYTES);
      const std::size_t first = bytes < QUEUE_BYTES - at ? bytes : QUEUE_BYTES - at;
      std::fwrite(ring_ + at, 1, first, stdout);
      std::fwrite(ring_, 1, bytes - first, stdout);
      if (unsaid > 0) {
        std::fprintf(stdout,
                     "[%10.3f ms] trace dropped %llu lines: its queue of %zu lines (%zu KiB) was full, standard output not read"
                     " in time (%llu in all)\n",
                     dropped_at, static_cast<unsigned long long>(unsaid), QUEUE_LINES, QUEUE_BYTES / 1024,
                     static_cast<unsigned long long>(dropped));
      }
      std::fflush(stdout);
#if defined(__unix__) || defined(__APPLE__)
      funlockfile(stdout);
#endif
      lock();
      head_ += bytes;  // room again for the threads that trace
      used_ -= bytes;
      lines_ -= count;
      written_count_ += count;
      said_dropped_ = dropped;
      const bool done = last && lines_ == 0 && dropped_ == said_dropped_;
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
  char ring_[QUEUE_BYTES];            // the lines queued, [head_, head_ + used_) modulo its size, each ending in a newline
  std::uint64_t head_ = 0;           // where the first line queued starts (counted from the start, not wrapped)
  std::size_t used_ = 0;             // bytes queued
  std::size_t lines_ = 0;            // lines queued
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
