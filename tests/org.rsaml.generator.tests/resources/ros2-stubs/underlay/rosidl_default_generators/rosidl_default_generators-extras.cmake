# SPDX-License-Identifier: EPL-2.0
# As ROS 2's rosidl_default_generators, which finds every generator and type support it groups;
# here only the generators Debian packages: C and C++ message code.
find_package(rosidl_cmake REQUIRED)
find_package(rosidl_generator_c REQUIRED)
find_package(rosidl_generator_cpp REQUIRED)
