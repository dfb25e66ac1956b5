# SPDX-License-Identifier: EPL-2.0
"""Stand-in for ROS 2's launch package (see ../../README.md): records what a launch file returns."""

from launch import actions, substitutions  # noqa: F401  (as launch, which imports its submodules)


class LaunchDescription:
    def __init__(self, initial_entities=None, *, deprecated_reason=None):
        self.entities = list(initial_entities or [])
