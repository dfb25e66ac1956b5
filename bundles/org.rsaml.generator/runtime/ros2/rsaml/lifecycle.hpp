/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The base of the managed nodes of an RsaML architecture (modules whose lifecycle is managed): an
// rclcpp_lifecycle node with the same schedule as a plain node (rsaml/scheduling.hpp). A node is
// created unconfigured; the generated class creates its publishers and subscriptions when it is
// configured and its timers when it is activated, and publishes and reacts only while active.
#pragma once

#include <atomic>
#include <cstring>
#include <string>

#include <rclcpp_lifecycle/lifecycle_node.hpp>

#include "rsaml/scheduling.hpp"

namespace rsaml_ros2 {

class ScheduledLifecycleNode : public rclcpp_lifecycle::LifecycleNode, public Schedule {
 public:
  using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

  ScheduledLifecycleNode(const std::string& name, const rclcpp::NodeOptions& options, std::string module, int core)
      : rclcpp_lifecycle::LifecycleNode(name, options),
        Schedule(static_cast<rclcpp_lifecycle::LifecycleNode&>(*this), module, core),
        module_(std::move(module)) {}

 /** "inactive" or "active" while the node is configured; else null. */
  const char* rsaml_configured_state() const override {
    return active_.load() ? "active" : configured_.load() ? "inactive" : nullptr;
  }

 protected:
  /** Whether the node is active: its releases and reactions run only then. */
  bool rsaml_active() const { return active_.load(); }

  /** Records a transition's outcome (active or not) and says it in the trace: "state MODULE active". */
  void rsaml_state(bool active, const char* state) {
    active_.store(active);
    configured_.store(active || std::strcmp(state, "inactive") == 0);
    trace("state " + module_ + " " + state);
  }

 private:
  std::string module_;
  std::atomic<bool> active_{false};
  std::atomic<bool> configured_{false};
};

}  // namespace rsaml_ros2
