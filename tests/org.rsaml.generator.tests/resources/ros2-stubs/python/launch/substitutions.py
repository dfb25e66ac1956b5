# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch.substitutions: names the argument or path it stands for; perform() resolves it
in a stand-in context (launch_configurations: the arguments' values; package_shares: package folders)."""

import os


def perform(value, context):
    return value.perform(context) if hasattr(value, 'perform') else value


class LaunchConfiguration:
    def __init__(self, variable_name, *, default=None):
        self.variable_name = variable_name
        self.default = default

    def perform(self, context):
        return perform(context.launch_configurations[self.variable_name], context)

    def __repr__(self):
        return '$(' + self.variable_name + ')'


class PathJoinSubstitution:
    def __init__(self, substitutions):
        self.substitutions = list(substitutions)

    def perform(self, context):
        return os.path.join(*[perform(s, context) for s in self.substitutions])

    def __repr__(self):
        return '/'.join(repr(s) if hasattr(s, 'perform') else s for s in self.substitutions)
