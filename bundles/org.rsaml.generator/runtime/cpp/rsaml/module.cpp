/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Modules: their activations, their worker threads, their reactions; and the links between their ports.
#include "rsaml/module.hpp"

#include <limits>

#include "rsaml/internal.hpp"
#include "rsaml/ports.hpp"
#include "rsaml/realtime.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

using internal::consume;
using internal::stall_since;
using internal::thread_cpu_time;

namespace {

thread_local Activation* current_activation = nullptr;

}  // namespace

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

std::uint64_t Module::mail_dropped() {
  std::lock_guard<InheritingLock> lock(mail_mutex_);
  return mail_dropped_;
}

void Module::start_worker() {
  if (!worker_.joinable()) {
    worker_ = std::thread([this] { run_worker(); });
    system_.place(worker_.native_handle(), name_, *this);
  }
}

void Module::stop_worker() {
  {
    std::lock_guard<InheritingLock> lock(mail_mutex_);
    stopping_ = true;
  }
  mail_mutex_.notify();  // its one worker
  if (worker_.joinable()) {
    worker_.join();
  }
}

void Module::run_worker() {
  Trace::line("lock " + name_ + " " + mutex_.protocol());
  const std::string sched = system_.schedule_worker(name_, unbounded_data_);
  if (reactions_) {
    reactions_->sched = sched;
  }
  for (;;) {
    Mail mail;
    std::size_t slot;
    std::uint64_t dropped;
    std::uint64_t unsaid;
    {
      std::lock_guard<InheritingLock> lock(mail_mutex_);
      while (!stopping_ && mail_count_ == 0) {
        mail_mutex_.wait();
      }
      if (stopping_) {
        return;
      }
      slot = mail_head_;  // the message keeps its slot (and its data its port's) until it is handled
      mail = mail_[slot];
      dropped = mail_dropped_;
      unsaid = dropped - mail_said_;
      mail_said_ = dropped;
    }
    if (unsaid > 0) {
      // said here, by the worker (of the default priority when its reactions are aperiodic), never by a sender
      Trace::report(internal::mailbox_dropped(name_, unsaid, dropped, false));
    }
    {
      // A reaction's job is released by the arrival of the data that starts it.
      Activation activation(*this, mail.wave, false, mail.arrived);
      mail.target->receive(slot, mail);
    }
    {
      std::lock_guard<InheritingLock> lock(mail_mutex_);
      mail_head_ = (mail_head_ + 1) % MAILBOX_SLOTS;
      --mail_count_;
    }
  }
}

bool Module::first_in_wave(std::uint64_t wave) {
  std::uint64_t& seen = waves_[wave % WAVES];
  if (seen == wave) {
    return false;
  }
  seen = wave;
  return true;
}

std::string internal::mailbox_dropped(const std::string& module, std::uint64_t dropped, std::uint64_t in_all, bool closing) {
  const std::string slots = "its " + std::to_string(MAILBOX_SLOTS) + " slots were taken";
  return "mailbox " + module + " dropped " +
         (closing ? std::to_string(in_all) + " messages in all: " + slots + ", its worker behind the senders"
                  : std::to_string(dropped) + " messages: " + slots + " (" + std::to_string(in_all) + " in all)");
}

void Module::start_step(std::uint64_t wave) {
  Activation activation(*this, wave, false, Clock::now());
  first_in_wave(wave);
  trace("start " + name_);
  on_start();
  publish_outputs();
}

Nanos Module::timed_release(const std::string& label, Clock::time_point release, const std::function<void()>& body,
                            Nanos busy) {
  Activation activation(*this, system_.new_wave(), true, release);
  const Clock::time_point locked = Clock::now();
  const Nanos cpu = thread_cpu_time();
  first_in_wave(activation.wave);
  trace("release " + label);
  if (busy.count() > 0) {
    consume(busy);
  }
  body();
  return stall_since(locked, cpu, activation.waited);
}

void Module::run_action(const char* label, Nanos offset, const std::function<void()>& body) {
  Activation* activation = Activation::current();
  if (activation && activation->timed && offset.count() > 0) {
    // Other activations of this module may run while this one waits for the action's start date.
    const Clock::time_point unlocked = Clock::now();
    activation->lock.unlock();
    const bool go_on = system_.sleep_until(activation->release + offset);
    activation->lock.lock();
    activation->waited += std::chrono::duration_cast<Nanos>(Clock::now() - unlocked);
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
    if (!first_in_wave(activation->wave)) {
      return false;
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
    const Nanos stall = stall_since(started, cpu, activation ? activation->waited : Nanos(0));
    system_.reaction_done(*reactions_, arrived, started, Clock::now(), thread_cpu_time() - cpu, stall);
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

}  // namespace rsaml
