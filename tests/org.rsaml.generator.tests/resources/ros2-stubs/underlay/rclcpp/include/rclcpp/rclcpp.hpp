/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for rclcpp (see ../../../../README.md): the parts generated code uses, with the
// signatures of rclcpp Humble to Rolling, so that a wrong argument, a missing override or a
// clock mix-up fails to compile as it would against rclcpp. Bodies do nothing: code built
// against it links but does not run.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// rcl/time.h
enum rcl_clock_type_t { RCL_CLOCK_UNINITIALIZED = 0, RCL_ROS_TIME, RCL_SYSTEM_TIME, RCL_STEADY_TIME };

namespace rclcpp {

// rclcpp/node_options.hpp
class NodeOptions {
 public:
  NodeOptions() = default;
  NodeOptions& use_intra_process_comms(bool) { return *this; }
};

// rclcpp/duration.hpp
class Duration {
 public:
  Duration(std::int32_t seconds, std::uint32_t nanoseconds) : ns_(seconds * 1000000000LL + nanoseconds) {}
  Duration(std::chrono::nanoseconds nanoseconds) : ns_(nanoseconds.count()) {}  // NOLINT: implicit, as in rclcpp
  static Duration from_nanoseconds(std::int64_t nanoseconds) { return Duration(std::chrono::nanoseconds(nanoseconds)); }
  std::int64_t nanoseconds() const { return ns_; }
  bool operator<(const Duration& rhs) const { return ns_ < rhs.ns_; }
  bool operator>=(const Duration& rhs) const { return ns_ >= rhs.ns_; }

 private:
  std::int64_t ns_;
};

// rclcpp/time.hpp: comparing times of different clock types throws in rclcpp.
class Time {
 public:
  explicit Time(std::int64_t nanoseconds = 0, rcl_clock_type_t clock_type = RCL_SYSTEM_TIME)
      : ns_(nanoseconds), type_(clock_type) {}
  std::int64_t nanoseconds() const { return ns_; }
  rcl_clock_type_t get_clock_type() const { return type_; }
  bool ros_time_is_active() { return false; }
  Time operator+(const Duration& rhs) const { return Time(ns_ + rhs.nanoseconds(), type_); }
  Duration operator-(const Time& rhs) const { return Duration::from_nanoseconds(ns_ - rhs.ns_); }
  bool operator<(const Time& rhs) const { return ns_ < rhs.ns_; }
  bool operator>=(const Time& rhs) const { return ns_ >= rhs.ns_; }

 private:
  std::int64_t ns_;
  rcl_clock_type_t type_;
};

// rclcpp/clock.hpp
class Clock {
 public:
  using SharedPtr = std::shared_ptr<Clock>;
  explicit Clock(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME) : type_(clock_type) {}
  Time now() const { return Time(0, type_); }
  rcl_clock_type_t get_clock_type() const { return type_; }
  bool ros_time_is_active() { return false; }

 private:
  rcl_clock_type_t type_;
};

// rclcpp/qos.hpp
class QoS {
 public:
  QoS(size_t history_depth) : depth_(history_depth) {}  // NOLINT: implicit, as in rclcpp
  QoS& reliable() { return *this; }
  QoS& best_effort() { return *this; }
  QoS& keep_last(size_t depth) {
    depth_ = depth;
    return *this;
  }

 private:
  size_t depth_;
};

class SensorDataQoS : public QoS {
 public:
  SensorDataQoS() : QoS(5) {}
};

// rclcpp/qos_overriding_options.hpp
class QosOverridingOptions {
 public:
  static QosOverridingOptions with_default_policies(const std::string& id = {}) {
    (void)id;
    return QosOverridingOptions();
  }
};

// rclcpp/publisher_options.hpp, rclcpp/subscription_options.hpp
struct PublisherOptions {
  QosOverridingOptions qos_overriding_options;
};

class CallbackGroup;

struct SubscriptionOptions {
  QosOverridingOptions qos_overriding_options;
  std::shared_ptr<CallbackGroup> callback_group;
};

// rclcpp/publisher.hpp
template <typename MessageT>
class Publisher {
 public:
  using SharedPtr = std::shared_ptr<Publisher<MessageT>>;
  void publish(const MessageT& message) { (void)message; }
  void publish(std::unique_ptr<MessageT> message) { (void)message; }
};

// rclcpp/subscription.hpp
template <typename MessageT>
class Subscription {
 public:
  using SharedPtr = std::shared_ptr<Subscription<MessageT>>;
};

// rclcpp/callback_group.hpp
enum class CallbackGroupType { MutuallyExclusive, Reentrant };

class CallbackGroup {
 public:
  using SharedPtr = std::shared_ptr<CallbackGroup>;
  CallbackGroup(CallbackGroupType group_type, bool automatically_add_to_executor_with_node = true)
      : type_(group_type), automatic_(automatically_add_to_executor_with_node) {}
  CallbackGroupType type() const { return type_; }
  bool automatically_add_to_executor_with_node() const { return automatic_; }

 private:
  CallbackGroupType type_;
  bool automatic_;
};

// rclcpp/timer.hpp (Jazzy and later: a callback may take the call's times)
struct TimerInfo {
  Time expected_call_time;
  Time actual_call_time;
};

class TimerBase {
 public:
  using SharedPtr = std::shared_ptr<TimerBase>;
  using WeakPtr = std::weak_ptr<TimerBase>;
  virtual ~TimerBase() = default;
  void cancel() { canceled_ = true; }
  bool is_canceled() { return canceled_; }
  void reset() { canceled_ = false; }
  std::chrono::nanoseconds time_until_trigger() { return std::chrono::nanoseconds(0); }

 private:
  bool canceled_ = false;
};

// rclcpp/node_interfaces/node_base_interface.hpp, node_timers_interface.hpp
namespace node_interfaces {
class NodeBaseInterface {
 public:
  using SharedPtr = std::shared_ptr<NodeBaseInterface>;
  virtual ~NodeBaseInterface() = default;
  CallbackGroup::SharedPtr create_callback_group(CallbackGroupType group_type,
                                                bool automatically_add_to_executor_with_node = true) {
    return std::make_shared<CallbackGroup>(group_type, automatically_add_to_executor_with_node);
  }
  const char* get_fully_qualified_name() const { return "/"; }
};
class NodeTimersInterface {
 public:
  using SharedPtr = std::shared_ptr<NodeTimersInterface>;
  virtual ~NodeTimersInterface() = default;
};
}  // namespace node_interfaces

// rclcpp/node.hpp: not copyable, no default constructor, a virtual destructor.
class Node : public std::enable_shared_from_this<Node> {
 public:
  using SharedPtr = std::shared_ptr<Node>;
  explicit Node(const std::string& node_name, const NodeOptions& options = NodeOptions())
      : Node(node_name, "", options) {}
  Node(const std::string& node_name, const std::string& namespace_, const NodeOptions& options = NodeOptions())
      : clock_(std::make_shared<Clock>(RCL_ROS_TIME)) {
    (void)node_name;
    (void)namespace_;
    (void)options;
  }
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  virtual ~Node() = default;

  const char* get_name() const { return ""; }
  const char* get_namespace() const { return "/"; }

  template <typename MessageT>
  typename Publisher<MessageT>::SharedPtr create_publisher(const std::string& topic_name, const QoS& qos,
                                                           const PublisherOptions& options = PublisherOptions()) {
    (void)topic_name;
    (void)qos;
    (void)options;
    return nullptr;
  }

  // rclcpp accepts, among others, callbacks taking std::shared_ptr<const MessageT>.
  template <typename MessageT, typename CallbackT>
  typename Subscription<MessageT>::SharedPtr create_subscription(const std::string& topic_name, const QoS& qos,
                                                                 CallbackT&& callback,
                                                                 const SubscriptionOptions& options = SubscriptionOptions()) {
    static_assert(std::is_invocable_v<CallbackT, std::shared_ptr<const MessageT>>,
                  "subscription callback must accept std::shared_ptr<const MessageT>");
    (void)topic_name;
    (void)qos;
    (void)callback;
    (void)options;
    return nullptr;
  }

  template <typename DurationRepT, typename DurationT, typename CallbackT>
  TimerBase::SharedPtr create_wall_timer(std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback) {
    static_assert(std::is_invocable_v<CallbackT>, "timer callback takes no argument");
    (void)period;
    (void)callback;
    return nullptr;
  }

  // Only these parameter types exist in ROS 2 (rclcpp/parameter_value.hpp).
  template <typename ParameterT>
  ParameterT declare_parameter(const std::string& name, const ParameterT& default_value) {
    static_assert(std::is_same_v<ParameterT, bool> || std::is_same_v<ParameterT, std::int64_t> ||
                      std::is_same_v<ParameterT, double> || std::is_same_v<ParameterT, std::string>,
                  "not a ROS 2 parameter type");
    (void)name;
    return default_value;
  }

  CallbackGroup::SharedPtr create_callback_group(CallbackGroupType group_type,
                                                bool automatically_add_to_executor_with_node = true) {
    return std::make_shared<CallbackGroup>(group_type, automatically_add_to_executor_with_node);
  }

  Clock::SharedPtr get_clock() { return clock_; }
  std::shared_ptr<node_interfaces::NodeBaseInterface> get_node_base_interface() { return nullptr; }
  std::shared_ptr<node_interfaces::NodeTimersInterface> get_node_timers_interface() { return nullptr; }
  Time now() const { return clock_->now(); }

 private:
  Clock::SharedPtr clock_;
};

// rclcpp/create_timer.hpp: a timer on the given clock (the node's follows use_sim_time).
template <typename NodeT, typename CallbackT>
TimerBase::SharedPtr create_timer(NodeT node, Clock::SharedPtr clock, Duration period, CallbackT&& callback,
                                  CallbackGroup::SharedPtr group = nullptr, bool autostart = true) {
  static_assert(std::is_convertible_v<NodeT, Node*> || std::is_convertible_v<NodeT, std::shared_ptr<Node>>,
                "create_timer takes the node");
  static_assert(std::is_invocable_v<CallbackT> || std::is_invocable_v<CallbackT, const TimerInfo&>,
                "timer callback takes nothing or the timer's call times");
  (void)group;
  (void)autostart;
  // As rclcpp, through the node's interfaces.
  std::shared_ptr<node_interfaces::NodeBaseInterface> base = node->get_node_base_interface();
  std::shared_ptr<node_interfaces::NodeTimersInterface> timers = node->get_node_timers_interface();
  (void)base;
  (void)timers;
  (void)clock;
  (void)period;
  (void)callback;
  return nullptr;
}

// rclcpp/create_timer.hpp: the same through the node's interfaces (what a lifecycle node offers too).
template <typename CallbackT>
TimerBase::SharedPtr create_timer(std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
                                  std::shared_ptr<node_interfaces::NodeTimersInterface> node_timers, Clock::SharedPtr clock,
                                  Duration period, CallbackT&& callback, CallbackGroup::SharedPtr group = nullptr,
                                  bool autostart = true) {
  static_assert(std::is_invocable_v<CallbackT> || std::is_invocable_v<CallbackT, const TimerInfo&>,
                "timer callback takes nothing or the timer's call times");
  (void)node_base;
  (void)node_timers;
  (void)clock;
  (void)period;
  (void)callback;
  (void)group;
  (void)autostart;
  return nullptr;
}

// rclcpp/exceptions/exceptions.hpp: what a wrong parameter or ROS argument raises.
namespace exceptions {
class InvalidParameterValueException : public std::runtime_error {
  using std::runtime_error::runtime_error;
};
class InvalidParameterTypeException : public std::runtime_error {
 public:
  InvalidParameterTypeException(const std::string& name, const std::string message)
      : std::runtime_error("parameter '" + name + "' has invalid type: " + message) {}
};
class InvalidQosOverridesException : public std::runtime_error {
  using std::runtime_error::runtime_error;
};
class RCLInvalidROSArgsError : public std::runtime_error {
 public:
  explicit RCLInvalidROSArgsError(const std::string& prefix) : std::runtime_error(prefix) {}
};
class UnknownROSArgsError : public std::runtime_error {
 public:
  explicit UnknownROSArgsError(std::vector<std::string>&& unknown) : std::runtime_error("found unknown ROS arguments"), unknown_ros_args(unknown) {}
  const std::vector<std::string> unknown_ros_args;
};
}  // namespace exceptions

// rclcpp/utilities.hpp, rclcpp/executors.hpp
class InitOptions {};
enum class SignalHandlerOptions { All, SigInt, SigTerm, None };
inline void init(int argc, char const* const* argv, const InitOptions& init_options = InitOptions(),
                 SignalHandlerOptions signal_handler_options = SignalHandlerOptions::All) {
  (void)argc;
  (void)argv;
  (void)init_options;
  (void)signal_handler_options;
}
inline void spin(std::shared_ptr<Node> node) { (void)node; }
inline bool shutdown() { return true; }
inline bool ok() { return false; }

// rclcpp/executor.hpp
class Executor {
 public:
  using SharedPtr = std::shared_ptr<Executor>;
  virtual ~Executor() = default;
  void add_callback_group(CallbackGroup::SharedPtr group_ptr,
                          std::shared_ptr<node_interfaces::NodeBaseInterface> node_ptr, bool notify = true) {
    (void)group_ptr;
    (void)node_ptr;
    (void)notify;
  }
  void add_node(std::shared_ptr<Node> node_ptr, bool notify = true) {
    (void)node_ptr;
    (void)notify;
  }
  void add_node(std::shared_ptr<node_interfaces::NodeBaseInterface> node_ptr, bool notify = true) {
    (void)node_ptr;
    (void)notify;
  }
  virtual void spin() = 0;
  void spin_once(std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) { (void)timeout; }
  void cancel() {}
  bool is_spinning() { return false; }
};

namespace executors {
class SingleThreadedExecutor : public Executor {
 public:
  void spin() override {}
};
class MultiThreadedExecutor : public Executor {
 public:
  void spin() override {}
};
}  // namespace executors

}  // namespace rclcpp
