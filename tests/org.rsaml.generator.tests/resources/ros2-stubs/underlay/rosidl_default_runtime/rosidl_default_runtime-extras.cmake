# SPDX-License-Identifier: EPL-2.0
# As ROS 2's rosidl_default_runtime: the run-time parts of generated messages.
find_package(rosidl_runtime_c REQUIRED)
find_package(rosidl_runtime_cpp REQUIRED)
