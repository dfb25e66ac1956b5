# SPDX-License-Identifier: EPL-2.0
"""Stand-in for ROS 2's launch_ros package (see ../../README.md)."""

from launch_ros import actions, descriptions, parameter_descriptions, substitutions  # noqa: F401
