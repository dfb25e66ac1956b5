/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet
import org.rsaml.generator.internal.Names

/**
 * The launch tests: the package's, test/test_&lt;pkg&gt;_launch.py (launch_testing, run by colcon test where
 * launch_testing_ament_cmake is installed): it starts the package's nodes with its launch file, lets
 * them run, stops them, and checks from the summary every node prints at exit that messages reached
 * the entry ports that modules with timed releases feed, and that every process exited cleanly; and,
 * with packages perLayer or perProcessor, one in each package of nodes (packageTest).
 */
class Ros2LaunchTestTemplate extends Ros2Template {

	/** How long the nodes run before they are stopped, in seconds. */
	static val RUN_S = 5

	/** How long a package's launch test waits for the message it checks, in seconds (the nodes' start included). */
	static val WAIT_S = 60

	val extension Ros2Names rosNames
	val extension org.rsaml.generator.internal.cxx.CxxNames names

	new(Ros2Context context) {
		super(context)
		this.rosNames = context.rosNames
		this.names = context.names
	}

	/** Text inside a Python docstring: one line, its backslashes and double quotes escaped. */
	def private docstring(String text) {
		Names.comment(text).replace("\\", "\\\\").replace("\"", "\\\"")
	}

	/** The path of the launch test of a package of nodes (packages perLayer or perProcessor), in that package. */
	def path(Ros2Packages.NodePackage np) {
		"test/test_" + np.name + "_launch.py"
	}

	/**
	 * The port whose messages a package's launch test waits for: the first output port of a node of
	 * the package with timed releases, which publishes without any other package's nodes; null when
	 * no node of the package has one.
	 */
	def private published(Ros2Packages.NodePackage np) {
		np.modules.filter[!releases.empty].map[outputs].flatten.head
	}

	/**
	 * The launch test of a package of nodes (packages perLayer or perProcessor): starts its nodes
	 * alone, each in a process of its own (with the lifecycle manager of the runtime package for its
	 * managed ones), and checks that one message of a node of the package arrives on its topic, or,
	 * when no node of the package publishes on its own, says so in its docstring and checks only that
	 * the nodes start and exit cleanly.
	 */
	def packageTest(Ros2Packages.NodePackage np) {
		val port = published(np)
		val managed = np.modules.filter[rosNames.managed(it)].toList
		val type = if (port === null) null else rosType(port).split("::")
		'''
			# «banner»
			"""The launch test of package «np.name», the nodes of «docstring(np.holds)» (launch_testing; colcon test
			runs it where launch_testing_ament_cmake is installed): starts each node of the package alone, in a process
			of its own, with the parameters the nodes declare (the model's values; the parameters file is the launch
			package's)«IF !managed.empty», the lifecycle manager of «context.packages.runtime» bringing the managed ones to active«ENDIF»,
			«IF port !== null»
				and checks that a message of node «port.module.rosNode» (port «port.qualifiedName») arrives on its topic
				«topic(port)» («type.join("/")») within «WAIT_S» s, and that every process exits cleanly.
			«ELSE»
				and checks that every process exits cleanly. No node of this package publishes on its own (none with
				timed releases has an output port), so no message is checked here: the launch test of «pkg»
				checks the messages between the packages' nodes.
			«ENDIF»
			"""
			import time
			import unittest

			import launch
			from launch_ros.actions import Node
			import launch_testing
			import launch_testing.actions
			import launch_testing.asserts
			import pytest
			«IF port !== null»
				import rclpy
				from rclpy.qos import qos_profile_sensor_data
				from «type.get(0)».«type.get(1)» import «type.get(2)»

				TOPIC = «py(topic(port))»
			«ENDIF»


			@pytest.mark.launch_test
			def generate_test_description():
			    return launch.LaunchDescription([
			        «FOR m : np.modules»
			        	Node(package=«py(np.name)», executable=«py(m.executable)», name=«py(m.rosNode)», output='screen'«IF rosNames.managed(m)»,
			        	     arguments=[«py(Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(managed.size))»], sigterm_timeout=«py(Ros2Shutdown.sigtermTimeoutS(managed.size))»«ENDIF»),
			        «ENDFOR»
			        «IF !managed.empty»
			        	Node(package=«py(context.packages.runtime)», executable=«py(rosNames.lifecycleManagerExecutable)», name=«py(np.name + "_lifecycle_manager")»,
			        	     output='screen', sigterm_timeout=«py(Ros2Shutdown.sigtermTimeoutS(managed.size))»,
			        	     parameters=[{'node_names': [«FOR m : managed SEPARATOR ", "»«py(m.rosNode)»«ENDFOR»], 'node_deadline_ms': «Ros2Shutdown.NODE_DEADLINE_MS»}]),
			        «ENDIF»
			        launch_testing.actions.ReadyToTest(),
			    ])
			«IF port !== null»


				class TestOneMessageFlows(unittest.TestCase):

				    def test_a_message_arrives(self, proc_output):
				        rclpy.init()
				        try:
				            node = rclpy.create_node(«py("test_" + np.name + "_listener")»)
				            received = []
				            # Best effort takes what a reliable and a best-effort publisher send alike.
				            node.create_subscription(«type.get(2)», TOPIC, received.append, qos_profile_sensor_data)
				            until = time.monotonic() + «WAIT_S»
				            while not received and time.monotonic() < until:
				                rclpy.spin_once(node, timeout_sec=0.1)
				            self.assertTrue(received, 'no message on ' + TOPIC + ' within «WAIT_S» s')
				        finally:
				            rclpy.shutdown()
			«ELSE»


				class TestNodesRun(unittest.TestCase):

				    def test_nodes_run(self, proc_output):
				        time.sleep(5)
			«ENDIF»


			@launch_testing.post_shutdown_test()
			class TestExit(unittest.TestCase):

			    def test_every_process_exited_cleanly(self, proc_info):
			        launch_testing.asserts.assertExitCodes(proc_info)
		'''
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
