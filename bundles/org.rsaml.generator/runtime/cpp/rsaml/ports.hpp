/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Ports and links: output and entry ports, and the inhibitors and suppressors between them.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rsaml/clock.hpp"
#include "rsaml/module.hpp"
#include "rsaml/system.hpp"
#include "rsaml/trace.hpp"

namespace rsaml {

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
class Input final : public MailTarget {
 public:
  using Handler = std::function<void(const T&)>;
  Input(Module& owner, const std::string& port, Handler handler)
      : owner_(owner), name_(owner.name() + "." + port), handler_(std::move(handler)), slots_(new T[MAILBOX_SLOTS]()) {
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

  /**
   * On the sender's thread: the data becomes the port's latest value, and a message for the owner's worker, copied
   * (assigned) into the port's slot of the mailbox slot it takes, both under the owner's mailbox lock. Nothing is
   * allocated here but what T's copy assignment allocates, and nothing the worker allocated is freed here.
   */
  void deliver(const T& data, const std::string* from, std::uint64_t sequence, std::uint64_t wave, Link* replacing) {
    owner_.post(Mail{this, wave, Clock::time_point{}, from, sequence, replacing}, [this, &data](std::size_t slot) {
      pending_ = data;
      fresh_ = true;
      if (slot < MAILBOX_SLOTS) {
        slots_[slot] = data;
      }
    });
  }

  /** On the owner's worker: the message's data, in its slot, to the handler (not copied). */
  void receive(std::size_t slot, const Mail& mail) override {
    ++received_;
    if (Trace::enabled()) {
      Trace::line("recv " + name_ + " <- " + *mail.from + " #" + std::to_string(mail.sequence) +
                  (mail.replacing ? " by " + mail.replacing->name() : std::string()));
    }
    handler_(slots_[slot]);
  }

 private:
  /** Called with the owner's lock held, when one of its activations starts. */
  void latch() {
    std::lock_guard<InheritingLock> lock(owner_.mailbox_lock());
    if (fresh_) {
      value_ = pending_;
      fresh_ = false;
    }
  }

  Module& owner_;
  std::string name_;
  Handler handler_;
  std::vector<Link*> suppressors_;
  std::unique_ptr<T[]> slots_;  // MAILBOX_SLOTS values, made with the port: a message's data, at its mailbox slot's index
  T value_{};
  T pending_{};  // the latest value sent, under the owner's mailbox lock
  bool fresh_ = false;
  std::uint64_t received_ = 0;
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
