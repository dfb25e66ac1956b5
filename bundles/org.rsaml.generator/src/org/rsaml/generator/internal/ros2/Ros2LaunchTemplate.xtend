/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.generator.internal.Names
import org.rsaml.model.support.RsamlLabels
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.OneMachineCpus

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
			# analysis's real-time priority, each node's data arrivals on one at priority 0 of the analysis; see the README):
			«IF rosNames.containers.exists[processor !== null]»
				# one container (one process) per processor of the model's deployment, pinned with taskset to
				# the processor's core where the model names one«IF rosNames.containers.exists[processor === null]», and one for the modules no processor names«ENDIF»«IF unclaimedUsed»;
				# the processes of the processors without a core on the CPUs no processor claims, as the C++ program's threads«ENDIF».
			«ELSE»
				# all in one process.
			«ENDIF»
			# The nodes of a container exchange messages within the process (intra-process communication): a
			# message published is shared by the subscriptions there, neither copied nor serialized.
			# «pkg»_processes.launch.py starts a process per node instead. Arguments:
		«ELSE»
			# Starts every module of the architecture as a node in a process of its own«IF rosNames.containers.exists[core >= 0]», pinned with
			# taskset to the core of its processor where the model names one«IF unclaimedUsed» (else on the CPUs no processor claims)«ENDIF»«ENDIF». Arguments:
		«ENDIF»
		# namespace:=NS (all nodes and topics under NS), use_sim_time:=true, simulated_load:=0.9 (every
		# timed job busy-works 90 % of its modeled execution time)«IF hosted», host:=NAME (only the nodes of
		# the processors on host NAME; main: those without a host; empty, the default: every node)«ENDIF»«IF !rosNames.topicArguments.empty»;
		# for each topic the model names, «rosNames.topicArguments.values.head»:=NAME and the like (the topic takes that name)«ENDIF»;
		# params_file:=PATH (the nodes' parameters; default: config/«pkg».params.yaml of this package).
		«IF unclaimedUsed»
			import os
		«ENDIF»
		import re

		import yaml

		from launch import LaunchDescription
		from launch.actions import DeclareLaunchArgument, OpaqueFunction
		«IF hosted»
			from launch.conditions import IfCondition
			from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression
		«ELSE»
			from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
		«ENDIF»
		«IF composed»
			from launch_ros.actions import ComposableNodeContainer«IF !rosNames.managedModules.empty», Node«ENDIF»
			from launch_ros.descriptions import ComposableNode
		«ELSE»
			from launch_ros.actions import Node
		«ENDIF»
		from launch_ros.parameter_descriptions import ParameterValue
		from launch_ros.substitutions import FindPackageShare

		# The times each node declares, in the model's units (the parameters file may set them).
		TIMES = {
		    «FOR e : context.timeNames.entrySet»
		    	«py(e.key)»: («FOR n : e.value»«py(n)», «ENDFOR»),
		    «ENDFOR»
		}


		def node_parameters(path, namespace, topics):
		    """The parameters file's values for each node: its section over the '/**' one, flattened. A QoS
		    override of a topic follows the topic's name as remapped (topics: the model's name -> the name it
		    takes) and, when relative, the namespace: ROS 2 names the override after the resolved topic."""
		    ns = namespace.strip('/')

		    def refuse(node, what):
		        return RuntimeError('%s:%d: %s' % (path, node.start_mark.line + 1, what))

		    def resolve(topic):
		        topic = topics.get(topic, topic)
		        return topic if topic.startswith('/') else '/' + '/'.join(x for x in (ns, topic) if x)

		    try:
		        with open(path, encoding='utf-8') as f:
		            loader = yaml.SafeLoader(f)
		            try:
		                root = loader.get_single_node()

		                def flat(node, prefix, out):
		                    if not isinstance(node, yaml.MappingNode):
		                        raise refuse(node, 'the parameters of a node are a mapping (name: value), not %s' % node.tag.rsplit(':', 1)[-1])
		                    for key, value in node.value:
		                        name = prefix + str(loader.construct_object(key, deep=True))
		                        if isinstance(value, yaml.MappingNode):
		                            flat(value, name + '.', out)
		                        else:
		                            out[name] = (value, loader.construct_object(value, deep=True))
		                    return out

		                sections = {}
		                if root is not None:
		                    if not isinstance(root, yaml.MappingNode):
		                        raise refuse(root, 'a ROS 2 parameters file maps node names to their ros__parameters')
		                    for key, value in root.value:
		                        node = str(loader.construct_object(key, deep=True)).lstrip('/')
		                        node = node[len(ns) + 1:] if ns and node.startswith(ns + '/') else node
		                        body = dict((str(loader.construct_object(k)), v) for k, v in value.value) if isinstance(value, yaml.MappingNode) else {}
		                        if 'ros__parameters' not in body:
		                            raise refuse(value, "node '%s' has no ros__parameters: indent its parameters under a line 'ros__parameters:'" % node)
		                        sections[node] = flat(body['ros__parameters'], '', {})
		            finally:
		                loader.dispose()
		    except OSError as e:
		        raise RuntimeError('%s: cannot read the parameters file (%s); params_file:=PATH names another' % (path, e.strerror)) from None
		    except yaml.YAMLError as e:
		        mark = getattr(e, 'problem_mark', None)
		        raise RuntimeError('%s:%s: not YAML: %s' % (path, mark.line + 1 if mark else 1, getattr(e, 'problem', None) or e)) from None

		    def of(node):
		        values = {}
		        for section in ('**', node):
		            for name, (source, value) in sections.get(section, {}).items():
		                time = re.fullmatch(r'.+\.(?:period|min_interval|duration)_(ns|us|ms|s)', name)
		                if time and section == node and name not in TIMES[node]:
		                    raise refuse(source, "node '%s' has no parameter %s (its times: %s): the model changed; rename or remove the line"
		                                 % (node, name, ', '.join(TIMES[node]) or 'none'))
		                if time and name in TIMES[node]:
		                    if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
		                        raise refuse(source, '%s of node %s must be a positive number of %s (the unit its name ends with), not %r'
		                                     % (name, node, time.group(1), value))
		                    value = float(value)  # a time written without a decimal point
		                if name.startswith('qos_overrides.'):
		                    «IF composed»
		                    	if (name.endswith('.history') and value == 'keep_all') or (name.endswith('.depth') and value == 0):
		                    	    raise refuse(source, '%s: %r: the nodes of a container share messages within the process (intra-process'
		                    	                 ' communication), which needs a keep_last history of depth 1 or more; keep that here, or'
		                    	                 ' start the nodes with «pkg»_processes.launch.py' % (name, value))
		                    «ENDIF»
		                    topic, _, policy = name[len('qos_overrides.'):].rpartition('.')
		                    topic, _, entity = topic.rpartition('.')
		                    name = 'qos_overrides.%s.%s.%s' % (resolve(topic), entity, policy)
		                values[name] = value
		        return values
		    return of


		«IF unclaimedUsed»
			# The CPUs the processors with a core claim, by the host argument ('': one machine starts every host, each host's
			# cores on CPUs of their own, as the C++ program; a host's name: its cores). As the C++ program keeps the threads of
			# the modules without a core off them, the processes of the processors without a core run on the CPUs left.
			CLAIMED = {«FOR e : OneMachineCpus.claimed(plan.architecture).entrySet.filter[hosted || key.empty] SEPARATOR ", "»«py(e.key)»: [«FOR c : e.value SEPARATOR ", "»«c»«ENDFOR»]«ENDFOR»}


			def cpu_list(cpus):
			    """CPUs as a short list, as taskset takes them: 0-3,6."""
			    runs = []
			    for cpu in sorted(cpus):
			        if runs and runs[-1][1] == cpu - 1:
			            runs[-1][1] = cpu
			        else:
			            runs.append([cpu, cpu])
			    return ','.join(str(a) if a == b else '%d-%d' % (a, b) for a, b in runs)


			def unclaimed(name, host):
			    """The launch prefix of process `name`, of a processor without a core: as the C++ program places the threads of
			    the modules without a core, it runs on the CPUs this launch may use that no processor claims (taskset, every thread
			    it starts included) and says so; where no processor claims a CPU, where the operating system puts it (no prefix);
			    where every CPU is claimed, the same, and it says so: then it shares the processors' cores, whose verdicts do not
			    hold."""
			    claimed = set(CLAIMED.get(host, ()))
			    if not claimed:
			        return None
			    cpus = set(os.sched_getaffinity(0)) - claimed
			    if not cpus:
			        return ("sh -c 'echo \"RsaML: cpu %s no unclaimed core: default (the processors claim CPUs %s: it runs on them)\" >&2; "
			                "exec \"$0\" \"$@\"'" % (name, cpu_list(claimed)))
			    return ("sh -c 'if taskset -c {cpus} true 2>/dev/null; then echo \"RsaML: cpu {name} cores {cpus} unclaimed\" >&2; "
			            "exec taskset -c {cpus} \"$0\" \"$@\"; fi; echo \"RsaML: cpu {name} cores {cpus} unclaimed not available: default\" >&2; "
			            "exec \"$0\" \"$@\"'").format(name=name, cpus=cpu_list(cpus))


		«ENDIF»
		def launch_setup(context):
		    namespace = LaunchConfiguration('namespace')
		    «IF unclaimedUsed»
		    	host = «IF hosted»LaunchConfiguration('host').perform(context)«ELSE»''«ENDIF»
		    «ENDIF»
		    topics = {«FOR t : rosNames.topicArguments.entrySet SEPARATOR ", "»«py(t.key)»: LaunchConfiguration(«py(t.value)»).perform(context)«ENDFOR»}
		    values = node_parameters(LaunchConfiguration('params_file').perform(context), namespace.perform(context), topics)
		    parameters = {'use_sim_time': LaunchConfiguration('use_sim_time'),
		                  'rsaml.simulated_load': ParameterValue(LaunchConfiguration('simulated_load'), value_type=float)}
		    «IF !rosNames.topicArguments.empty»
		    	# The topics the model names, each remapped to its argument's value (the same name by default).
		    	remappings = [«FOR t : rosNames.topicArguments.entrySet SEPARATOR ",\n              "»(«py(t.key)», LaunchConfiguration(«py(t.value)»))«ENDFOR»]
		    «ENDIF»
		    return [
		        «IF composed»
		        	«FOR c : rosNames.containers»
		        		«IF c.processor !== null»
		        			# Processor '«Names.comment(c.processor.name)»'«IF c.core >= 0»: CPU core «c.core»«ENDIF».
		        		«ELSEIF rosNames.containers.size > 1»
		        			# The modules no processor names.
		        		«ENDIF»
		        		ComposableNodeContainer(
		        		    name=«py(c.name)», namespace=namespace, package=«py(context.packages.runtime)»,
		        		    executable=«py(rosNames.containerExecutable)», output='screen', parameters=[parameters],«shutdown(c)»«IF c.core >= 0»
		        		    prefix=«prefix(c.processor, c.core)»,«ELSEIF unclaimedUsed»
		        		    prefix=unclaimed(«py(c.name)», host),«ENDIF»«IF hosted»
		        		    condition=«onHost(c.processor)»,«ENDIF»
		        		    composable_node_descriptions=[
		        		        «FOR m : c.modules»
		        		        	ComposableNode(package=«py(context.nodePackage(m))», plugin=«py(context.plugin(m))», name=«py(m.rosNode)»,
		        		        	               namespace=namespace, parameters=[values(«py(m.rosNode)»), parameters]«remap»,
		        		        	               extra_arguments=[{'use_intra_process_comms': True}]),
		        		        «ENDFOR»
		        		    ]),
		        	«ENDFOR»
		        «ELSE»
		        	«FOR m : plan.modules»
		        		Node(package=«py(context.nodePackage(m))», executable=«py(m.executable)», name=«py(m.rosNode)»,
		        		     namespace=namespace, parameters=[values(«py(m.rosNode)»), parameters]«remap», output='screen'«IF m.managed»,«shutdown(container(m)).replaceFirst(",$", "")»«ENDIF»«IF m.core >= 0»,
		        		     prefix=«prefix(m.processor, m.core)»«ELSEIF unclaimedUsed»,
		        		     prefix=unclaimed(«py(m.rosNode)», host)«ENDIF»«IF hosted»,
		        		     condition=«onHost(m.processor)»«ENDIF»),
		        	«ENDFOR»
		        «ENDIF»
		        «FOR c : rosNames.containers.filter[modules.exists[managed]]»
		        	# The managed nodes«IF c.processor !== null» of processor '«Names.comment(c.processor.name)»'«ENDIF»: configured, then activated, once they are up; deactivated and cleaned up when the launch stops.
		        	Node(package=«py(context.packages.runtime)», executable=«py(rosNames.lifecycleManagerExecutable)», name=«py(c.name.replaceFirst("_container$", "") + "_lifecycle_manager")»,
		        	     namespace=namespace, output='screen', sigterm_timeout=«py(Ros2Shutdown.sigtermTimeoutS(managedCount(c)))»,
		        	     parameters=[{'node_names': [«FOR m : c.modules.filter[managed] SEPARATOR ", "»«py(m.rosNode)»«ENDFOR»],
		        	                  'node_deadline_ms': «Ros2Shutdown.NODE_DEADLINE_MS»}]«IF hosted»,
		        	     condition=«onHost(c.processor)»«ENDIF»),
		        «ENDFOR»
		    ]


		def generate_launch_description():
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
		        DeclareLaunchArgument('params_file',
		                              default_value=PathJoinSubstitution([FindPackageShare(«py(pkg)»), 'config', «py(pkg + ".params.yaml")»]),
		                              description="The nodes' parameters file (ROS 2's format; times in the model's units)"),
		        OpaqueFunction(function=launch_setup),
		    ])
	'''

	/** How many managed nodes the lifecycle manager of container c brings down. */
	def private managedCount(Ros2Names.Container c) {
		c.modules.filter[rosNames.managed(it)].size
	}

	/** The container (the processor, and so the lifecycle manager) of module m. */
	def private container(org.rsaml.analysis.plan.PlannedModule m) {
		rosNames.containers.findFirst[modules.contains(m)]
	}

	/**
	 * What a process with managed nodes of container c is given to serve them while their lifecycle
	 * manager brings them down (Ros2Shutdown): its grace, and ros2 launch's wait before SIGTERM.
	 */
	def private shutdown(Ros2Names.Container c) {
		val n = managedCount(c)
		if (n == 0) return ""
		" arguments=[" + py(Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(n)) + "], sigterm_timeout=" + py(Ros2Shutdown.sigtermTimeoutS(n)) + ","
	}

	/** Every node takes the remappings of the topics the model names, if it names any. */
	def private remap() {
		if (rosNames.topicArguments.empty) "" else ", remappings=remappings"
	}

	/**
	 * Whether the launch places the processes of processors without a core on the CPUs no processor claims: some
	 * processor claims a core, and some process has none of its own. Every such process is, an EDF processor's too, as
	 * the C++ program confines those modules' threads ({@link OneMachineCpus#claimed}, docs/timing.md, "EDF beside
	 * processors with cores"): there the kernel refuses SCHED_DEADLINE, and the releases run at their ranks, saying so.
	 */
	def private unclaimedUsed() {
		OneMachineCpus.claimed(plan.architecture).values.exists[!empty] && rosNames.containers.exists[core < 0]
	}

	/** Whether some processor is on another host: then the launch files take the argument host. */
	def private hosted() {
		plan.architecture.processors.exists[!RsamlLabels.host(it).empty]
	}

	/** The condition that starts what runs on processor p's host (main: no host) when host:= names it or is empty. */
	def private onHost(org.rsaml.model.Processor p) {
		"IfCondition(PythonExpression([\"'\", LaunchConfiguration('host'), " + py("' in ('', " + py(RsamlLabels.hostName(p)) + ")") + "]))"
	}

	/**
	 * The launch prefix of a process of processor p, on its core: without host:= one machine starts
	 * every host's processes, and another host's core that the analysis counts apart from this one's
	 * is pinned to a CPU of its own there (OneMachineCpus, as the C++ program does); with host:=, to
	 * its core; the process is told which (RSAML_CPU), and its nodes' threads stay there. The shell gets "host=" and
	 * the argument's value as "$0".
	 */
	def private prefix(org.rsaml.model.Processor p, int core) {
		val cpu = OneMachineCpus.cpu(p)
		if (!hosted || cpu < 0 || cpu == core) return py(taskset(core))
		"[" + py("sh -c 'case \"$0\" in host=) c=" + cpu + ";; *) c=" + core + ";; esac; "
			+ "if taskset -c $c true 2>/dev/null; then export RSAML_CPU=$c; exec taskset -c $c \"$@\"; fi; "
			+ "echo \"RsaML: CPU core $c not available: $1 runs unpinned\" >&2; exec \"$@\"' host=") + ", LaunchConfiguration('host')]"
	}

	/**
	 * The launch prefix that pins a process (and every thread it starts) to one CPU core with
	 * util-linux's taskset, telling the process which (RSAML_CPU: its nodes pin their threads there, not
	 * to the model's core); on a machine without that core the process starts unpinned and says so,
	 * as the C++ runtime does, instead of failing to start. Launch splits it as a shell would, and
	 * the shell gets the node's command line as "$0" "$@".
	 */
	def private taskset(int core) {
		"sh -c 'if taskset -c " + core + " true 2>/dev/null; then export RSAML_CPU=" + core + "; exec taskset -c " + core + " \"$0\" \"$@\"; fi; "
			+ "echo \"RsaML: CPU core " + core + " not available: $0 runs unpinned\" >&2; exec \"$0\" \"$@\"'"
	}
}
