/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet

/**
 * The package's launch test, test/test_&lt;pkg&gt;_launch.py (launch_testing, run by colcon test where
 * launch_testing_ament_cmake is installed): it starts the package's nodes with its launch file, lets
 * them run, stops them, and checks from the summary every node prints at exit that messages reached
 * the entry ports that modules with timed releases feed, and that every process exited cleanly.
 */
class Ros2LaunchTestTemplate extends Ros2Template {

	/** How long the nodes run before they are stopped, in seconds. */
	static val RUN_S = 5

	new(Ros2Context context) {
		super(context)
	}

	/** The path of the test in the package. */
	def path() {
		"test/test_" + pkg + "_launch.py"
	}

	/**
	 * The entry ports, as the nodes' summaries name them (layer/module:port), that a connection from
	 * a module with timed releases feeds: those receive messages whatever the others do.
	 */
	def private fedPorts() {
		val ports = new TreeSet<String>
		for (f : plan.flows.filter[!source.module.releases.empty]) {
			ports += f.target.module.qualifiedName + ":" + f.target.name
		}
		ports
	}

	def launchTest() '''
		# «banner»
		# The package's launch test (launch_testing; colcon test runs it where launch_testing_ament_cmake
		# is installed): starts the nodes with launch/«pkg».launch.py, lets them run «RUN_S» s, stops them,
		# and checks from the summary each node prints at exit that messages reached every entry port a
		# module with timed releases feeds, and that every process exited cleanly.
		import os
		import re
		import time
		import unittest

		from ament_index_python.packages import get_package_share_directory
		import launch
		from launch.actions import IncludeLaunchDescription
		from launch.launch_description_sources import PythonLaunchDescriptionSource
		import launch_testing
		import launch_testing.actions
		import launch_testing.asserts
		import pytest

		# Entry ports a module with timed releases feeds, as the nodes' summaries name them (layer/module:port).
		FED_PORTS = [«FOR p : fedPorts SEPARATOR ', '»«py(p)»«ENDFOR»]


		@pytest.mark.launch_test
		def generate_test_description():
		    launch_file = os.path.join(get_package_share_directory(«py(pkg)»), 'launch', «py(pkg + ".launch.py")»)
		    return launch.LaunchDescription([
		        IncludeLaunchDescription(PythonLaunchDescriptionSource(launch_file)),
		        launch_testing.actions.ReadyToTest(),
		    ])


		class TestNodesRun(unittest.TestCase):

		    def test_nodes_run(self, proc_output):
		        time.sleep(«RUN_S»)


		@launch_testing.post_shutdown_test()
		class TestMessagesFlowed(unittest.TestCase):

		    def test_every_fed_port_received_messages(self, proc_output):
		        text = ''.join(output.text.decode(errors='replace') for output in proc_output)
		        for port in FED_PORTS:
		            found = re.search('summary ' + re.escape(port) + r' messages (\d+)', text)
		            self.assertIsNotNone(found, 'no summary of entry port ' + port)
		            self.assertGreater(int(found.group(1)), 0, 'no message reached entry port ' + port)

		    def test_every_process_exited_cleanly(self, proc_info):
		        launch_testing.asserts.assertExitCodes(proc_info)
	'''
}
