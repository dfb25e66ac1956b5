# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch_ros.actions: keeps the arguments the launch file gives, with launch_ros's keywords."""


class Node:
    def __init__(self, *, executable, package=None, name=None, namespace=None, exec_name=None, parameters=None,
                 remappings=None, ros_arguments=None, arguments=None, output=None, **other):
        self.package = package
        self.executable = executable
        self.name = name
        self.namespace = namespace
        self.parameters = parameters
        self.remappings = remappings
        self.output = output
        self.other = other


class ComposableNodeContainer(Node):
    def __init__(self, *, name, namespace, composable_node_descriptions=None, **kwargs):
        super().__init__(name=name, namespace=namespace, **kwargs)
        self.composable_node_descriptions = list(composable_node_descriptions or [])
