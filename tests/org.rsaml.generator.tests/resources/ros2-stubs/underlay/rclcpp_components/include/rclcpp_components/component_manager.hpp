/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for rclcpp_components/component_manager.hpp and node_instance_wrapper.hpp: the parts a
// component container that places its nodes on executors of its own overrides.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>

namespace rclcpp_components {

class NodeInstanceWrapper {
 public:
  std::shared_ptr<rclcpp::node_interfaces::NodeBaseInterface> get_node_base_interface() { return nullptr; }
};

class ComponentManager : public rclcpp::Node {
 public:
  explicit ComponentManager(std::weak_ptr<rclcpp::Executor> executor = std::weak_ptr<rclcpp::Executor>(),
                            std::string node_name = "ComponentManager",
                            const rclcpp::NodeOptions& node_options = rclcpp::NodeOptions())
      : rclcpp::Node(node_name, node_options), executor_(executor) {}
  ~ComponentManager() override = default;

 protected:
  virtual void add_node_to_executor(std::uint64_t node_id) { (void)node_id; }
  virtual void remove_node_from_executor(std::uint64_t node_id) { (void)node_id; }

  std::weak_ptr<rclcpp::Executor> executor_;
  std::map<std::uint64_t, NodeInstanceWrapper> node_wrappers_;
};

}  // namespace rclcpp_components
