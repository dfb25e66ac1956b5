# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch.substitutions.LaunchConfiguration: names the argument it stands for."""


class LaunchConfiguration:
    def __init__(self, variable_name, *, default=None):
        self.variable_name = variable_name
        self.default = default

    def __repr__(self):
        return '$(' + self.variable_name + ')'
