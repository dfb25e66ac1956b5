# SPDX-License-Identifier: EPL-2.0
include("${rclcpp_components_DIR}/rclcpp_components_register_node.cmake")
include("${rclcpp_components_DIR}/rclcpp_components_register_nodes.cmake")
