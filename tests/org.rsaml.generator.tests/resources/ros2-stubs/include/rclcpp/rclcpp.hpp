/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for rclcpp (see ../../README.md): declarations only, same signatures as rclcpp.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>

namespace rclcpp {

class NodeOptions {
 public:
  NodeOptions() = default;
};

class QoS {
 public:
  QoS(size_t history_depth);  // NOLINT: implicit, as in rclcpp
};

template <typename MessageT>
class Publisher {
 public:
  using SharedPtr = std::shared_ptr<Publisher<MessageT>>;
  void publish(const MessageT& message);
};

template <typename MessageT>
class Subscription {
 public:
  using SharedPtr = std::shared_ptr<Subscription<MessageT>>;
};

class TimerBase {
 public:
  using SharedPtr = std::shared_ptr<TimerBase>;
  virtual ~TimerBase() = default;
};

class Node : public std::enable_shared_from_this<Node> {
 public:
  using SharedPtr = std::shared_ptr<Node>;
  Node(const std::string& node_name, const std::string& namespace_, const NodeOptions& options = NodeOptions());
  virtual ~Node();

  template <typename MessageT>
  typename Publisher<MessageT>::SharedPtr create_publisher(const std::string& topic_name, const QoS& qos);

  // rclcpp accepts, among others, callbacks taking std::shared_ptr<const MessageT>.
  template <typename MessageT, typename CallbackT>
  typename Subscription<MessageT>::SharedPtr create_subscription(const std::string& topic_name, const QoS& qos,
                                                                 CallbackT&& callback) {
    static_assert(std::is_invocable_v<CallbackT, std::shared_ptr<const MessageT>>,
                  "subscription callback must accept std::shared_ptr<const MessageT>");
    (void)topic_name;
    (void)qos;
    (void)callback;
    return nullptr;
  }

  template <typename DurationRepT, typename DurationT, typename CallbackT>
  TimerBase::SharedPtr create_wall_timer(std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback) {
    static_assert(std::is_invocable_v<CallbackT>, "timer callback takes no argument");
    (void)period;
    (void)callback;
    return nullptr;
  }
};

void init(int argc, char const* const* argv);
void spin(std::shared_ptr<Node> node);
bool shutdown();

}  // namespace rclcpp
