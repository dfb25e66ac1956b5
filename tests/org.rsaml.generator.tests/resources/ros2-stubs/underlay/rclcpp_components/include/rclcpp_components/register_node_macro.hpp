/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for rclcpp_components/register_node_macro.hpp (see ../../../../README.md). rclcpp's
// NodeFactoryTemplate<NodeT> makes the node with std::make_shared<NodeT>(options) and takes its
// node base interface: the class must be a concrete rclcpp::Node constructible from NodeOptions.
#pragma once

#include <memory>
#include <type_traits>

#include <rclcpp/rclcpp.hpp>

namespace rclcpp_components {
template <typename NodeT>
bool registered();
}  // namespace rclcpp_components

#define RCLCPP_COMPONENTS_REGISTER_NODE(NodeClass)                                                           \
  static_assert(std::is_base_of_v<rclcpp::Node, NodeClass>, "a component is an rclcpp::Node");            \
  static_assert(std::is_constructible_v<NodeClass, const rclcpp::NodeOptions&>,                            \
                "a component is constructed from rclcpp::NodeOptions");                                    \
  template <>                                                                                              \
  bool rclcpp_components::registered<NodeClass>() {                                                        \
    auto node = std::make_shared<NodeClass>(rclcpp::NodeOptions());                                       \
    return node->get_node_base_interface() != nullptr;                                                     \
  }
