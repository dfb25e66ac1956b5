/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The base of every generated module class: its activations, its worker thread, its reactions.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "rsaml/clock.hpp"
#include "rsaml/measure.hpp"
#include "rsaml/realtime.hpp"

namespace rsaml {

class System;
class Module;
class Link;
class MailTarget;

/**
 * How many messages a module's mailbox holds: slots made with the module (and, for each entry port, as many values of
 * its type), filled by the senders and emptied by the module's worker without allocating. A message that finds them
 * all taken is dropped and counted (docs/timing.md, "Memory between threads").
 */
constexpr std::size_t MAILBOX_SLOTS = 64;

/** A message in a module's mailbox: plain values (its data is in its entry port's slot of the same index). */
struct Mail {
  MailTarget* target = nullptr;  // the entry port it arrived on
  std::uint64_t wave = 0;
  Clock::time_point arrived{};
  const std::string* from = nullptr;  // the sending port's name
  std::uint64_t sequence = 0;         // the sending port's count
  Link* replacing = nullptr;          // the suppressor it was sent by, if any
};

/** An entry port as its module's mailbox sees it: what the worker calls with a message and its slot. */
class MailTarget {
 public:
  /** On the module's worker, its lock held: handles the message whose data is in the port's slot `slot`. */
  virtual void receive(std::size_t slot, const Mail& mail) = 0;

 protected:
  ~MailTarget() = default;
};

/** A module's reactions and what its worker thread observed of them. */
struct Reactions {
  Module* module;
  std::string label;
  JobBounds bounds;
  std::string sched;  // the scheduling the worker got, as the trace says it
  JobStats stats;
};

/**
 * A module's two locks (rsaml/realtime.hpp, the lock class the ROS 2 nodes use too): its lock, recursive, held while any
 * of its activations runs, and its mailbox's, shared by the releases that send to it and its worker, which waits on its
 * condition.
 */
using rsaml_realtime::InheritingLock;

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
  std::unique_lock<InheritingLock> lock;
  /** How long the lock was given up to wait for actions' start dates (not the job's stall). */
  Nanos waited{0};

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
  /**
   * Puts a message into the mailbox, for the worker: under the mailbox's lock, calls fill(slot) with the slot it takes
   * (fill copies the data into its entry port's slot of that index), or, when every slot is taken, drops the message,
   * counts it and calls fill(MAILBOX_SLOTS) (the port's latest value is still updated). Allocates nothing; the worker
   * says the drops (a line when it next takes a message, and the summary).
   */
  template <class Fill>
  void post(Mail mail, Fill&& fill);
  /** The mailbox's lock: also guards the entry ports' latest values, which the senders set and the activations take. */
  InheritingLock& mailbox_lock() { return mail_mutex_; }
  /** Messages dropped so far, every slot of the mailbox taken. */
  std::uint64_t mail_dropped();
  void start_worker();
  void stop_worker();
  void start_step(std::uint64_t wave);
  /**
   * Measures the module's reactions (a module that reacts to data calls it once, in its constructor):
   * each from the arrival that starts it to its completion, against bounds.
   */
  void measure_reactions(std::string label, JobBounds bounds);
  /**
   * Serves the module's data at the default priority (SCHED_OTHER), below every real-time thread, pinned to
   * the module's core all the same (`sched <module> worker default: it serves aperiodic reactions ...`): a module
   * whose reactions are aperiodic calls it in its constructor. The model bounds neither their arrivals nor their
   * load, and the analysis excludes them; at a real-time priority, a module offered more data than it can react
   * to would keep its worker always ready and take the real-time time of its CPU, which Linux's real-time
   * throttling (sched_rt_runtime_us) then takes back from every real-time thread there, the releases the
   * analysis proved included (docs/timing.md, "What is excluded, and said so").
   */
  void serve_data_unbounded() { unbounded_data_ = true; }
  /**
   * A reaction to the data that has arrived: runs body (the step functions and the sending of the
   * outputs) when begin_reaction() lets it, after the busy work, and measures it.
   */
  void react(Nanos min_interval, const std::function<void()>& body);
  /**
   * Runs one job of a timed release; busy: CPU time it consumes first (the --busy-work stand-in for
   * user code). Returns the job's stall: the time it held the module's lock, ready, without running
   * (its wall time from taking the lock to its end, minus its CPU time and its waits for actions'
   * start dates).
   */
  Nanos timed_release(const std::string& label, Clock::time_point release, const std::function<void()>& body,
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
  void run_worker();
  /** Whether the wave is new to the module (then noted): under its lock. */
  bool first_in_wave(std::uint64_t wave);
  /** How many waves the module remembers: those of the last WAVES waves of the system (a wave's number modulo WAVES). */
  static constexpr std::size_t WAVES = 1024;

  System& system_;
  std::string name_;
  int core_;
  std::string host_;
  int cpu_;
  InheritingLock mutex_{true};
  InheritingLock mail_mutex_{false};
  // The mailbox: a ring of MAILBOX_SLOTS messages, mail_count_ of them from mail_head_ on (the first, while the worker
  // handles it, still holds its slot); under mail_mutex_.
  std::array<Mail, MAILBOX_SLOTS> mail_{};
  std::size_t mail_head_ = 0;
  std::size_t mail_count_ = 0;
  std::uint64_t mail_dropped_ = 0;  // in all
  std::uint64_t mail_said_ = 0;     // of them, said by the worker
  bool stopping_ = false;
  std::thread worker_;
  std::array<std::uint64_t, WAVES> waves_{};  // the waves the module took part in, each at its number modulo WAVES; 0: none
  std::vector<std::function<void()>> latches_;
  int depth_ = 0;
  Clock::time_point last_reaction_{};
  bool reacted_ = false;
  Reactions* reactions_ = nullptr;  // owned by the system; null when not measured
  bool unbounded_data_ = false;  // its worker serves aperiodic reactions at the default priority
};

template <class Fill>
void Module::post(Mail mail, Fill&& fill) {
  {
    std::lock_guard<InheritingLock> lock(mail_mutex_);
    if (stopping_) {
      return;
    }
    if (mail_count_ == MAILBOX_SLOTS) {
      ++mail_dropped_;
      fill(MAILBOX_SLOTS);
      return;
    }
    const std::size_t slot = (mail_head_ + mail_count_) % MAILBOX_SLOTS;
    fill(slot);
    mail.arrived = Clock::now();
    mail_[slot] = mail;
    ++mail_count_;
  }
  mail_mutex_.notify();
}

}  // namespace rsaml
