# SPDX-License-Identifier: EPL-2.0
"""Stand-in for ROS 2's launch package (see ../../README.md): records what a launch file returns."""


class LaunchDescription:
    def __init__(self, entities=None):
        self.entities = list(entities or [])
