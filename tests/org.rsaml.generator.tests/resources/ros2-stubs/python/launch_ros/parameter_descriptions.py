# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch_ros.parameter_descriptions.ParameterValue, with launch_ros's keywords."""


class ParameterValue:
    def __init__(self, value, *, value_type=None):
        self.value = value
        self.value_type = value_type

    def __repr__(self):
        return 'ParameterValue(%r, %s)' % (self.value, getattr(self.value_type, '__name__', None))
