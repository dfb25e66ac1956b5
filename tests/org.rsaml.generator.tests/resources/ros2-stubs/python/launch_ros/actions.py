# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch_ros.actions.Node: keeps the arguments the launch file gives it."""


class Node:
    def __init__(self, *, package, executable, name=None, namespace=None, output=None, **other):
        self.package = package
        self.executable = executable
        self.name = name
        self.namespace = namespace
        self.output = output
        self.other = other
