/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.generator.internal.Names
import org.rsaml.model.support.RsamlLabels
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The two launch files, written by one template: &lt;pkg&gt;.launch.py starts the nodes as components
 * of the package's container (one container per processor with a deployment), and
 * &lt;pkg&gt;_processes.launch.py a process per node. Both take the same arguments and give every
 * node the same parameters.
 */
class Ros2LaunchTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
	}

	/** The launch file of the components in containers. */
	def composed() {
		launch(true)
	}

	/** The launch file of a process per node. */
	def processes() {
		launch(false)
	}

	def private launch(boolean composed) '''
		# «banner»
		«IF composed»
			# Starts every module of the architecture as an rclcpp component in a component container
			# («rosNames.containerExecutable»: each timed release on an executor thread of its own at the timing
			# analysis's real-time priority, data arrivals on the main executor; see the README):
			«IF rosNames.containers.exists[processor !== null]»
				# one container (one process) per processor of the model's deployment, pinned with taskset to
				# the processor's core where the model names one«IF rosNames.containers.exists[processor === null]», and one for the modules no processor names«ENDIF».
			«ELSE»
				# all in one process.
			«ENDIF»
			# «pkg»_processes.launch.py starts a process per node instead. Arguments:
		«ELSE»
			# Starts every module of the architecture as a node in a process of its own«IF rosNames.containers.exists[core >= 0]», pinned with
			# taskset to the core of its processor where the model names one«ENDIF». Arguments:
		«ENDIF»
		# namespace:=NS (all nodes and topics under NS), use_sim_time:=true, simulated_load:=0.9 (every
		# timed job busy-works 90 % of its modeled execution time)«IF hosted», host:=NAME (only the nodes of
		# the processors on host NAME; main: those without a host; empty, the default: every node)«ENDIF»«IF !rosNames.topicArguments.empty»;
		# for each topic the model names, «rosNames.topicArguments.values.head»:=NAME and the like (the topic takes that name)«ENDIF».
		from launch import LaunchDescription
		from launch.actions import DeclareLaunchArgument
		«IF hosted»
			from launch.conditions import IfCondition
			from launch.substitutions import LaunchConfiguration, PythonExpression
		«ELSE»
			from launch.substitutions import LaunchConfiguration
		«ENDIF»
		«IF composed»
			from launch_ros.actions import ComposableNodeContainer
			from launch_ros.descriptions import ComposableNode
		«ELSE»
			from launch_ros.actions import Node
		«ENDIF»
		from launch_ros.parameter_descriptions import ParameterValue


		def generate_launch_description():
		    namespace = LaunchConfiguration('namespace')
		    parameters = [{'use_sim_time': LaunchConfiguration('use_sim_time'),
		                   'rsaml.simulated_load': ParameterValue(LaunchConfiguration('simulated_load'), value_type=float)}]
		    «IF !rosNames.topicArguments.empty»
		    	# The topics the model names, each remapped to its argument's value (the same name by default).
		    	remappings = [«FOR t : rosNames.topicArguments.entrySet SEPARATOR ",\n              "»(«py(t.key)», LaunchConfiguration(«py(t.value)»))«ENDFOR»]
		    «ENDIF»
		    return LaunchDescription([
		        DeclareLaunchArgument('namespace', default_value='',
		                              description='Namespace of every node and topic (a second robot: another namespace)'),
		        DeclareLaunchArgument('use_sim_time', default_value='false',
		                              description='Run the nodes on the simulation clock (/clock)'),
		        DeclareLaunchArgument('simulated_load', default_value='0.0',
		                              description='Busy work of every timed job, as a fraction (0 to 1) of its modeled execution time'),
		        «IF hosted»
		        	DeclareLaunchArgument('host', default_value='',
		        	                      description='Start only the nodes of this host (main: the processors without one); empty: every node'),
		        «ENDIF»
		        «FOR t : rosNames.topicArguments.entrySet»
		        	DeclareLaunchArgument(«py(t.value)», default_value=«py(t.key)»,
		        	                      description=«py("Topic '" + t.key + "' of the model: the name it takes")»),
		        «ENDFOR»
		        «IF composed»
		        	«FOR c : rosNames.containers»
		        		«IF c.processor !== null»
		        			# Processor '«Names.comment(c.processor.name)»'«IF c.core >= 0»: CPU core «c.core»«ENDIF».
		        		«ELSEIF rosNames.containers.size > 1»
		        			# The modules no processor names.
		        		«ENDIF»
		        		ComposableNodeContainer(
		        		    name=«py(c.name)», namespace=namespace, package=«py(pkg)»,
		        		    executable=«py(rosNames.containerExecutable)», output='screen', parameters=parameters,«IF c.core >= 0»
		        		    prefix=«py(taskset(c.core))»,«ENDIF»«IF hosted»
		        		    condition=«onHost(c.processor)»,«ENDIF»
		        		    composable_node_descriptions=[
		        		        «FOR m : c.modules»
		        		        	ComposableNode(package=«py(pkg)», plugin=«py(context.plugin(m))», name=«py(m.rosNode)»,
		        		        	               namespace=namespace, parameters=parameters«remap»),
		        		        «ENDFOR»
		        		    ]),
		        	«ENDFOR»
		        «ELSE»
		        	«FOR m : plan.modules»
		        		Node(package=«py(pkg)», executable=«py(m.executable)», name=«py(m.rosNode)»,
		        		     namespace=namespace, parameters=parameters«remap», output='screen'«IF m.core >= 0»,
		        		     prefix=«py(taskset(m.core))»«ENDIF»«IF hosted»,
		        		     condition=«onHost(m.processor)»«ENDIF»),
		        	«ENDFOR»
		        «ENDIF»
		    ])
	'''

	/** Every node takes the remappings of the topics the model names, if it names any. */
	def private remap() {
		if (rosNames.topicArguments.empty) "" else ", remappings=remappings"
	}

	/** Whether some processor is on another host: then the launch files take the argument host. */
	def private hosted() {
		plan.architecture.processors.exists[!RsamlLabels.host(it).empty]
	}

	/** The condition that starts what runs on processor p's host (main: no host) when host:= names it or is empty. */
	def private onHost(org.rsaml.model.Processor p) {
		val host = RsamlLabels.host(p)
		"IfCondition(PythonExpression([\"'\", LaunchConfiguration('host'), " + py("' in ('', " + py(if (host.empty) "main" else host) + ")") + "]))"
	}

	/**
	 * The launch prefix that pins a process (and every thread it starts) to one CPU core with
	 * util-linux's taskset; on a machine without that core the process starts unpinned and says so,
	 * as the C++ runtime does, instead of failing to start. Launch splits it as a shell would, and
	 * the shell gets the node's command line as "$0" "$@".
	 */
	def private taskset(int core) {
		"sh -c 'if taskset -c " + core + " true 2>/dev/null; then exec taskset -c " + core + " \"$0\" \"$@\"; fi; "
			+ "echo \"RsaML: CPU core " + core + " not available: $0 runs unpinned\" >&2; exec \"$0\" \"$@\"'"
	}
}
