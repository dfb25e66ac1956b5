# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch_ros.descriptions.ComposableNode, with launch_ros's keywords."""


class ComposableNode:
    def __init__(self, *, package, plugin, name=None, namespace=None, parameters=None, remappings=None,
                 extra_arguments=None, condition=None):
        self.package = package
        self.plugin = plugin
        self.name = name
        self.namespace = namespace
        self.parameters = parameters
        self.remappings = remappings
        self.extra_arguments = extra_arguments
