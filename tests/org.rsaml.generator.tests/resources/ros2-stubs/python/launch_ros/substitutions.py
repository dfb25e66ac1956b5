# SPDX-License-Identifier: EPL-2.0
"""Stand-in for launch_ros.substitutions.FindPackageShare: a package's share folder, from the context."""


class FindPackageShare:
    def __init__(self, package):
        self.package = package

    def perform(self, context):
        return context.package_shares[self.package]

    def __repr__(self):
        return '$(find-pkg-share ' + self.package + ')'
