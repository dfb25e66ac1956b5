# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch.actions: the actions generated launch files use, with launch's keywords."""


class DeclareLaunchArgument:
    def __init__(self, name, *, default_value=None, description=None, choices=None, **other):
        self.name = name
        self.default_value = default_value
        self.description = description
        self.choices = choices
        self.other = other


class OpaqueFunction:
    def __init__(self, *, function, args=None, kwargs=None, **other):
        self.function = function
        self.args = args
        self.kwargs = kwargs
