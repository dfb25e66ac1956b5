/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The lifecycle manager of a package's managed nodes, started by both launch files: it configures
// and then activates each node its parameter node_names names (relative names resolve in its
// namespace), waiting for each to come up, whether it runs in a container or in a process of its
// own, and logs each node's state. It then stays until SIGINT or SIGTERM (ros2 launch stopping, or
// Ctrl-C), when it deactivates and cleans up every node it reached, the last one first, each within
// a deadline of its own (parameter node_deadline_ms), while their processes wait for it
// (rsaml/scheduling.hpp: spin, for as long as the launch files give them for all of this manager's
// nodes), and says how long each took. It exits with status 1 when a node refuses a transition or does
// not answer, and with status 2 (one line, rsaml/usage.hpp) when a parameter of its own is wrong.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <lifecycle_msgs/msg/state.hpp>
#include <lifecycle_msgs/msg/transition.hpp>
#include <lifecycle_msgs/srv/change_state.hpp>
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

#include "rsaml/usage.hpp"

namespace {

using lifecycle_msgs::msg::State;
using lifecycle_msgs::msg::Transition;
using lifecycle_msgs::srv::ChangeState;
using lifecycle_msgs::srv::GetState;
using Clock = std::chrono::steady_clock;

/**
 * How long each node is given to be deactivated and cleaned up, without the parameter node_deadline_ms
 * (which the launch files set): what a process waits for one managed node without its grace argument
 * (rsaml/scheduling.hpp: GRACE_WITHOUT_ARGUMENT_MS, 3 s) less a second for the answer's way back.
 */
constexpr std::int64_t NODE_DEADLINE_WITHOUT_PARAMETER_MS = 2000;

std::atomic<int> stop_signals{0};

void on_stop_signal(int) { stop_signals.fetch_add(1); }

bool stopping() { return stop_signals.load() > 0 || !rclcpp::ok(); }

/** Milliseconds since `start`. */
double since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

/** A managed node: its name and the clients of its lifecycle services. */
struct Managed {
  std::string name;
  rclcpp::Client<GetState>::SharedPtr get;
  rclcpp::Client<ChangeState>::SharedPtr change;
  bool reached = false;  // its services answered: it is brought down at the end
};

/**
 * The response to a request, or null when none came by `deadline` or, when `interruptible`, once
 * SIGINT or SIGTERM came.
 */
template <typename ServiceT>
typename ServiceT::Response::SharedPtr call(const rclcpp::Node::SharedPtr& node, const typename rclcpp::Client<ServiceT>::SharedPtr& client,
                                            typename ServiceT::Request::SharedPtr request, Clock::time_point deadline, bool interruptible) {
  auto future = client->async_send_request(request);
  while (rclcpp::ok() && Clock::now() < deadline && !(interruptible && stop_signals.load() > 0)) {
    if (rclcpp::spin_until_future_complete(node, future, std::chrono::milliseconds(50)) == rclcpp::FutureReturnCode::SUCCESS) {
      return future.get();
    }
  }
  return nullptr;
}

/** Brings one node to active: 0 when it is, 1 when it refused, -1 when SIGINT or SIGTERM came first. */
int activate(const rclcpp::Node::SharedPtr& node, Managed& m) {
  for (int waited = 0; !m.get->wait_for_service(std::chrono::seconds(1)) || !m.change->wait_for_service(std::chrono::seconds(1)); ++waited) {
    if (stopping()) {
      return -1;
    }
    if (waited % 10 == 9) {
      RCLCPP_INFO(node->get_logger(), "waiting for the managed node %s", m.name.c_str());
    }
  }
  m.reached = true;
  const auto forever = Clock::time_point::max();
  while (!stopping()) {
    auto state = call<GetState>(node, m.get, std::make_shared<GetState::Request>(), forever, true);
    if (!state) {
      return -1;
    }
    const std::uint8_t id = state->current_state.id;
    if (id == State::PRIMARY_STATE_ACTIVE) {
      RCLCPP_INFO(node->get_logger(), "%s is active", m.name.c_str());
      return 0;
    }
    auto request = std::make_shared<ChangeState::Request>();
    if (id == State::PRIMARY_STATE_UNCONFIGURED) {
      request->transition.id = Transition::TRANSITION_CONFIGURE;
    } else if (id == State::PRIMARY_STATE_INACTIVE) {
      request->transition.id = Transition::TRANSITION_ACTIVATE;
    } else {
      RCLCPP_ERROR(node->get_logger(), "%s is %s: it cannot be brought to active", m.name.c_str(), state->current_state.label.c_str());
      return 1;
    }
    auto changed = call<ChangeState>(node, m.change, request, forever, true);
    if (!changed) {
      return -1;
    }
    if (!changed->success) {
      RCLCPP_ERROR(node->get_logger(), "%s refused to %s (see its log)", m.name.c_str(),
                   request->transition.id == Transition::TRANSITION_CONFIGURE ? "configure" : "activate");
      return 1;
    }
  }
  return -1;
}

/**
 * Deactivates (when active) and cleans up one node by `deadline`: 0 when it is then unconfigured, else
 * 1. A successful cleanup is the node's word that it is unconfigured: its process may exit at once.
 * Says how long it took ("NODE is unconfigured; down in 143.2 ms"), the margin against its deadline.
 */
int bring_down(const rclcpp::Node::SharedPtr& node, Managed& m, Clock::time_point deadline) {
  const Clock::time_point started = Clock::now();
  auto state = call<GetState>(node, m.get, std::make_shared<GetState::Request>(), deadline, false);
  if (!state) {
    RCLCPP_ERROR(node->get_logger(), "%s did not say its state in time: it was not deactivated and cleaned up", m.name.c_str());
    return 1;
  }
  const std::uint8_t id = state->current_state.id;
  if (id == State::PRIMARY_STATE_UNCONFIGURED || id == State::PRIMARY_STATE_FINALIZED) {
    RCLCPP_INFO(node->get_logger(), "%s is %s; down in %.1f ms", m.name.c_str(), state->current_state.label.c_str(), since(started));
    return 0;
  }
  if (id != State::PRIMARY_STATE_ACTIVE && id != State::PRIMARY_STATE_INACTIVE) {
    RCLCPP_ERROR(node->get_logger(), "%s is %s: it cannot be cleaned up", m.name.c_str(), state->current_state.label.c_str());
    return 1;
  }
  for (const std::uint8_t transition : {Transition::TRANSITION_DEACTIVATE, Transition::TRANSITION_CLEANUP}) {
    if (transition == Transition::TRANSITION_DEACTIVATE && id != State::PRIMARY_STATE_ACTIVE) {
      continue;
    }
    auto request = std::make_shared<ChangeState::Request>();
    request->transition.id = transition;
    auto changed = call<ChangeState>(node, m.change, request, deadline, false);
    if (!changed || !changed->success) {
      RCLCPP_ERROR(node->get_logger(), "%s %s to %s (see its log)", m.name.c_str(), changed ? "refused" : "did not answer in time",
                   transition == Transition::TRANSITION_DEACTIVATE ? "deactivate" : "clean up");
      return 1;
    }
  }
  RCLCPP_INFO(node->get_logger(), "%s is unconfigured; down in %.1f ms", m.name.c_str(), since(started));
  return 0;
}

/** What main() does: the lifecycle manager's status. */
int manage(int argc, char** argv) {
  rclcpp::init(argc, argv, rclcpp::InitOptions(), rclcpp::SignalHandlerOptions::None);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  int status = 0;
  {
    auto node = std::make_shared<rclcpp::Node>("lifecycle_manager");
    const std::int64_t deadline_ms = node->declare_parameter<std::int64_t>("node_deadline_ms", NODE_DEADLINE_WITHOUT_PARAMETER_MS);
    if (deadline_ms <= 0) {
      throw rsaml_ros2::UsageError("parameter node_deadline_ms is " + std::to_string(deadline_ms) + ": it must be a positive number of"
                                   " milliseconds each managed node is given to be brought down; set it so (-p node_deadline_ms:=2000;"
                                   " the launch files set it)");
    }
    std::vector<Managed> managed;
    for (const std::string& name : node->declare_parameter<std::vector<std::string>>("node_names", std::vector<std::string>{})) {
      Managed m;
      m.name = name;
      try {
        m.get = node->create_client<GetState>(name + "/get_state");
        m.change = node->create_client<ChangeState>(name + "/change_state");
      } catch (const rclcpp::exceptions::NameValidationError& e) {
        throw rsaml_ros2::UsageError("parameter node_names: '" + name + "' is not the name of a node (" + e.error_msg +
                                     "); give the names of the managed nodes, e.g. -p node_names:=[lidar] (the launch files set it)");
      }
      managed.push_back(m);
    }
    for (Managed& m : managed) {
      const int result = activate(node, m);
      if (result != 0) {
        status = result > 0 ? 1 : 0;
        break;
      }
    }
    if (!stopping()) {
      RCLCPP_INFO(node->get_logger(), "%s; on SIGINT they are deactivated and cleaned up",
                  status == 0 ? "every managed node is active" : "not every managed node is active");
    }
    while (!stopping()) {
      rclcpp::spin_some(node);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    // Each node its own deadline: one slow to clean up does not take the time of those after it.
    const auto per_node = std::chrono::milliseconds(deadline_ms);
    for (auto m = managed.rbegin(); m != managed.rend(); ++m) {
      if (!m->reached) {
        continue;
      }
      RCLCPP_INFO(node->get_logger(), "bringing %s down within %lld ms", m->name.c_str(), static_cast<long long>(per_node.count()));
      if (bring_down(node, *m, Clock::now() + per_node) != 0) {
        status = 1;
      }
    }
  }
  rclcpp::shutdown();
  return status;
}

}  // namespace

int main(int argc, char* argv[]) {
  return rsaml_ros2::run_main(argc, argv, [argc, argv] { return manage(argc, argv); });
}
