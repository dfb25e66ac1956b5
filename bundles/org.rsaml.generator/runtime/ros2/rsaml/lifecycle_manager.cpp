/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The lifecycle manager of a package's managed nodes, started by both launch files: it configures
// and then activates each node its parameter node_names names (relative names resolve in its
// namespace), waiting for each to come up, whether it runs in a container or in a process of its
// own. It logs each node's state and exits once every one is active (with status 1 when a node
// refuses a transition; on SIGINT, quietly).
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <lifecycle_msgs/msg/state.hpp>
#include <lifecycle_msgs/msg/transition.hpp>
#include <lifecycle_msgs/srv/change_state.hpp>
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

namespace {

using lifecycle_msgs::msg::State;
using lifecycle_msgs::msg::Transition;
using lifecycle_msgs::srv::ChangeState;
using lifecycle_msgs::srv::GetState;

/** The response to a request, or null when ROS 2 shuts down first. */
template <typename ServiceT>
typename ServiceT::Response::SharedPtr call(const rclcpp::Node::SharedPtr& node, const typename rclcpp::Client<ServiceT>::SharedPtr& client,
                                            typename ServiceT::Request::SharedPtr request) {
  auto future = client->async_send_request(request);
  if (rclcpp::spin_until_future_complete(node, future) != rclcpp::FutureReturnCode::SUCCESS) {
    return nullptr;
  }
  return future.get();
}

/** Brings one node to active: 0 when it is, 1 when it refused, -1 when ROS 2 shut down first. */
int activate(const rclcpp::Node::SharedPtr& node, const std::string& name) {
  auto get = node->create_client<GetState>(name + "/get_state");
  auto change = node->create_client<ChangeState>(name + "/change_state");
  for (int waited = 0; !get->wait_for_service(std::chrono::seconds(1)) || !change->wait_for_service(std::chrono::seconds(1)); ++waited) {
    if (!rclcpp::ok()) {
      return -1;
    }
    if (waited % 10 == 9) {
      RCLCPP_INFO(node->get_logger(), "waiting for the managed node %s", name.c_str());
    }
  }
  while (rclcpp::ok()) {
    auto state = call<GetState>(node, get, std::make_shared<GetState::Request>());
    if (!state) {
      return -1;
    }
    const std::uint8_t id = state->current_state.id;
    if (id == State::PRIMARY_STATE_ACTIVE) {
      RCLCPP_INFO(node->get_logger(), "%s is active", name.c_str());
      return 0;
    }
    auto request = std::make_shared<ChangeState::Request>();
    if (id == State::PRIMARY_STATE_UNCONFIGURED) {
      request->transition.id = Transition::TRANSITION_CONFIGURE;
    } else if (id == State::PRIMARY_STATE_INACTIVE) {
      request->transition.id = Transition::TRANSITION_ACTIVATE;
    } else {
      RCLCPP_ERROR(node->get_logger(), "%s is %s: it cannot be brought to active", name.c_str(), state->current_state.label.c_str());
      return 1;
    }
    auto changed = call<ChangeState>(node, change, request);
    if (!changed) {
      return -1;
    }
    if (!changed->success) {
      RCLCPP_ERROR(node->get_logger(), "%s refused to %s (see its log)", name.c_str(),
                   request->transition.id == Transition::TRANSITION_CONFIGURE ? "configure" : "activate");
      return 1;
    }
  }
  return -1;
}

}  // namespace

int main(int argc, char* argv[]) {
  rclcpp::init(argc, argv);
  int status = 0;
  {
    auto node = std::make_shared<rclcpp::Node>("lifecycle_manager");
    const auto names = node->declare_parameter<std::vector<std::string>>("node_names", std::vector<std::string>{});
    for (const std::string& name : names) {
      const int result = activate(node, name);
      if (result != 0) {
        status = result > 0 ? 1 : 0;
        break;
      }
    }
  }
  rclcpp::shutdown();
  return status;
}
