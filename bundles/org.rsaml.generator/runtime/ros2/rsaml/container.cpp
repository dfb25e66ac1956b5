/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The component container of a processor: as rclcpp_components' component_container (a
// single-threaded executor for ROS 2's services), and each timed release of a node of this package
// on an executor thread of its own at its real-time priority, and the node's data arrivals on one at
// priority 0 of the analysis (rsaml/scheduling.hpp). Components of other packages run on the main
// executor. On SIGINT it serves its managed nodes until the lifecycle manager has deactivated and
// cleaned them up. A wrong argument of its own ends it with one line and status 2 (rsaml/usage.hpp); a
// component whose parameters are wrong is not loaded, and the container says why (rclcpp_components).
#include <map>
#include <memory>

#include <rclcpp/rclcpp.hpp>
#include <rclcpp_components/component_manager.hpp>

#include "rsaml/scheduling.hpp"

namespace rsaml_ros2 {
namespace {

class Container : public rclcpp_components::ComponentManager {
 public:
  using rclcpp_components::ComponentManager::ComponentManager;

  ~Container() override {
    for (auto& s : schedulers_) {
      s.second->stop();
    }
  }

 protected:
  void add_node_to_executor(std::uint64_t node_id) override {
    rclcpp_components::ComponentManager::add_node_to_executor(node_id);
    Schedule* node = Schedule::rsaml_of(node_wrappers_[node_id].get_node_base_interface().get());
    if (node != nullptr) {
      auto scheduler = std::make_unique<Scheduler>();
      scheduler->add(*node);
      schedulers_[node_id] = std::move(scheduler);
    }
  }

  void remove_node_from_executor(std::uint64_t node_id) override {
    auto found = schedulers_.find(node_id);
    if (found != schedulers_.end()) {
      found->second->stop();
      schedulers_.erase(found);
    }
    rclcpp_components::ComponentManager::remove_node_from_executor(node_id);
  }

 private:
  std::map<std::uint64_t, std::unique_ptr<Scheduler>> schedulers_;
};

}  // namespace
}  // namespace rsaml_ros2

int main(int argc, char* argv[]) {
  return rsaml_ros2::run_main(argc, argv, [argc, argv] {
    rsaml_ros2::init(argc, argv);
    {
      auto executor = std::make_shared<rclcpp::executors::SingleThreadedExecutor>();
      auto container = std::make_shared<rsaml_ros2::Container>(executor);
      executor->add_node(container);
      rsaml_ros2::spin(*executor);
    }
    rclcpp::shutdown();
    return 0;
  });
}
