/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The output's README.md, the architect's (created once, never overwritten), and GENERATED.md beside
 * it, regenerated every time with what this generation made of the model (the package layout, the
 * managed nodes, the topics, the parameters, the scheduling, the files that are the architect's), so
 * that a README written long ago never states stale facts: it links GENERATED.md.
 */
class Ros2ReadmeTemplate extends Ros2Template {

	/** The regenerated file the README links. */
	public static val GENERATED = "GENERATED.md"

	val extension CxxNames names
	val extension Ros2Names rosNames

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
	}

	/** The README the architect starts with: what the packages are, how to start them, and the link to GENERATED.md. */
	def readme() '''
		# «doc(plan.name)» for ROS 2

		ament_cmake packages of the RsaML architecture '«doc(plan.name)»', created by
		`rsaml generate --target ros2`, for ROS 2 Humble, Jazzy, Kilted and Rolling. This README is
		yours: created once, never overwritten; say here what your robot's packages are for.

		**[«GENERATED»](«GENERATED»)** is regenerated from the model every time: how to build, launch
		and tune the packages, which package holds which nodes, the topics, the parameters, the
		managed nodes, how the nodes are scheduled and which files are yours.

		```sh
		colcon build
		source install/setup.bash
		ros2 launch «pkg» «pkg».launch.py
		```
	'''

	/** GENERATED.md: the facts of this generation, regenerated every time. */
	def generated() '''
		<!-- «context.banner.replace("--", "- -")» Your notes go in README.md. -->
		# «doc(plan.name)» for ROS 2: what RsaML generated

		ament_cmake packages of the RsaML architecture '«doc(plan.name)»', created by
		`rsaml generate --target ros2`, for ROS 2 Humble, Jazzy, Kilted and Rolling: a node per module,
		each an rclcpp component of the library `«IF context.packages.single»«pkg»«ELSE»of its package«ENDIF»` and an executable of its own, a timer per
		periodic function, a topic per group of connected ports. This file is regenerated every time
		(edit the model, or README.md for notes of yours). Put this directory in a colcon
		workspace's `src/`, then:

		```sh
		colcon build
		source install/setup.bash
		ros2 launch «pkg» «pkg».launch.py                  # «IF rosNames.containers.size > 1»a process (component container) per processor«ELSE»all nodes in one process«ENDIF»
		ros2 launch «pkg» «pkg»_processes.launch.py        # a process per node
		ros2 launch «pkg» «pkg».launch.py namespace:=robot2 use_sim_time:=true
		```

		«IF !context.packages.single»
			The nodes are in packages of their own (`packages «plan.architecture.packages.literal»` in the model):
			«FOR np : context.packages.nodePackages SEPARATOR ", "»`«np.name»` («doc(np.holds)»)«ENDFOR»; each builds its nodes
			as components of its library and an executable each, and depends only on what they use. `«context.packages.runtime»`
			holds the scheduling runtime (a shared library every node links, so that the nodes of a container
			share it), the component container«IF !rosNames.managedModules.empty» and the lifecycle manager«ENDIF»; `«pkg»` the launch files and the
			parameters file«IF !context.generatedMessages.empty»; `«rosNames.interfacesPackage»` the message types«ENDIF». The model's `packages` chooses the layout
			(`single`, `perLayer`, `perProcessor`). Generating this directory again with another layout is
			refused while files of yours (your classes, and a `user.cmake` or `«Ros2Manifest.FILE»` that adds
			something) are in packages the new layout no longer builds them in, with the list of files to move
			or merge.

		«ENDIF»
		Topics are relative, so `namespace:=...` isolates a second robot.«IF !rosNames.topicArguments.empty» The topics the model names
		(«FOR t : rosNames.topicArguments.entrySet SEPARATOR ", "»`«t.key»`«ENDFOR») take another name with a launch argument each
		(«FOR t : rosNames.topicArguments.entrySet SEPARATOR ", "»`«t.value»:=NAME`«ENDFOR»), in every node.«ENDIF» The model's periods, minimum
		intervals and inhibitor/suppressor durations are node parameters in the model's units (the name
		says which: `detect.period_ms`) with the model's values as defaults; timers run on the node's
		clock, so `use_sim_time` works. Topics written by modules that read sensors use the sensor data
		QoS (best effort), the others are reliable; both can be overridden with
		`qos_overrides.<topic>.publisher|subscription.<policy>` parameters. Every parameter, with the
		model's value, is in `«pkg»/config/«pkg».params.yaml`, which both launch files load
		(`params_file:=PATH` loads another): edit it to tune the system without generating again (rebuild
		or use `params_file:=` for the installed copy). Its values win over the model's. A QoS override
		there names the topic as the model does; the launch files give it to the topic as remapped and
		namespaced, the name ROS 2 looks the override up by. A file they cannot take (not YAML, a time
		that is not a positive number, a time a node no longer has) is refused with its line. The file is
		yours and kept: `«pkg»/gen/«pkg».params.yaml`, regenerated every time and loaded by no launch file,
		is its complete current form, to copy from what yours lacks. Keep every node and parameter in yours:
		a node takes the model's value for one left out, and generating again names each one left out, every
		time, until it is back.
		«IF !rosNames.managedModules.empty»

		Managed nodes (`rclcpp_lifecycle`): «FOR m : rosNames.managedModules SEPARATOR ", "»`«m.rosNode»`«ENDFOR». Each starts unconfigured;
		*configure* creates its publishers and subscriptions, *activate* activates the publishers and
		starts its timers, *deactivate* stops both, *cleanup* and *shutdown* release them; while it is
		not active it publishes nothing and drops what arrives (an override of yours of `on_configure`
		and the like calls the generated one). Both launch files start `«rosNames.lifecycleManagerExecutable»`,
		which configures and activates them once they are up and, when the launch stops (SIGINT or
		SIGTERM, Ctrl-C), deactivates and cleans them up, the last first, each within «Ros2Shutdown.NODE_DEADLINE_MS / 1000.0» s of
		its own, before it exits; their processes serve them meanwhile, for at most «Ros2Shutdown.NODE_DEADLINE_MS / 1000.0» s per managed
		node of their lifecycle manager and «Ros2Shutdown.ANSWER_MS / 1000.0» s more, and the launch files let `ros2 launch` wait
		«Ros2Shutdown.EXIT_MS / 1000.0» s beyond that before it sends SIGTERM (`sigterm_timeout`). `ros2 lifecycle get` shows
		their states, `ros2 lifecycle set` changes them.
		«ENDIF»

		Messages are not copied on their way in: each subscription takes a `ConstSharedPtr`, which the
		node keeps as `in_<port>` (the latest message, null until the first arrives) and whose message
		`on_<port>` gets as a const reference. Each publication hands the middleware a `std::unique_ptr`
		(a copy of `out_<port>`, which keeps its value); in `«pkg».launch.py` the nodes of a container use
		intra-process communication, so the subscriptions in that process share the published message
		instead of copying or serializing it. Intra-process communication needs a `keep_last` history:
		keep it when overriding a topic's QoS, or use the processes launch file. To publish without the
		copy of `out_<port>`, an action or handler sends a message of its own with
		`send_<port>(std::make_unique<T>(...))`: it is published at once and handed over as it is (the
		subscriptions of the container get that very object), an inhibitor drops it as it would the
		port's value, and the publish that ends the activation skips that port (`out_<port>` is left as it was).
		«IF rosNames.containers.exists[processor !== null]»

		The model's deployment is kept: «pkg».launch.py starts one component container per processor,
		«FOR c : rosNames.containers SEPARATOR ", "»`«c.name»` («IF c.processor === null»the modules no processor names«ELSE»processor '«doc(c.processor.name)»'«IF c.core >= 0», core «c.core»«ENDIF»«ENDIF»)«ENDFOR».
		Processes of a processor with a core are started under `taskset -c CORE` (util-linux), in both
		launch files; on a machine without that core they start unpinned and say so.«IF rosNames.containers.exists[core >= 0] && rosNames.containers.exists[core < 0]»
		Those of the modules without a core run on the CPUs no processor claims, as the C++ program's threads of those
		modules, and say so (`cpu <process> cores 1 unclaimed`, or `no unclaimed core` when every CPU is claimed); an EDF
		processor's among them too, where the kernel, its deadline admission control on as by default, refuses its releases
		`SCHED_DEADLINE` (it admits a deadline thread only on every CPU), so that they run at their ranks and say
		`instead of EDF` (and `rsaml analyze` says its tasks are not analysed).«ENDIF»
		«ENDIF»

		The nodes are scheduled as `rsaml analyze` assumes: in the container `«rosNames.containerExecutable»`
		(and in each node's own executable) every timed release has a callback group of its own, served
		by a single-threaded executor on a thread of its own under `SCHED_FIFO` (`SCHED_RR` for round
		robin) at the analysis's rank, pinned to its processor's core; each node's data arrivals (its
		reactions, input handlers and link triggers) have a callback group of their own, served the same
		way at priority 0 of the analysis (`SCHED_FIFO`'s lowest priority, below every release); ROS 2's
		services run on the process's main executor at the default priority, and a node's activations
		hold its lock, so they never run at once. Where real-time priorities are not permitted (neither
		root nor `CAP_SYS_NICE` nor an `rtprio` limit), each of these threads says so on standard output
		and runs at the default priority: then the analysis's verdicts do not hold. Every node measures its jobs
		(release to completion, on the node's clock), prints `miss` and `overrun` lines as they happen
		and a `summary` line per release, for its reactions to data (arrival to completion) and per entry
		port at exit. The parameter
		`rsaml.simulated_load:=0.9` makes every job (timed release or reaction) busy-work 90 % of its modeled execution time, to see
		the timing before the code is written.

		`colcon test` runs the linters `«Ros2Manifest.FILE»` names as `<test_depend>` (through
		`ament_lint_auto`; `gen/` excluded) and the launch test `test/test_«pkg»_launch.py`
		(`launch_testing`: starts the nodes, stops them after a few seconds, and checks that messages
		reached every entry port a timed module feeds and that every process exited cleanly)«IF !context.packages.single»,
		and in each package of nodes its own launch test `test/test_<package>_launch.py` (its nodes
		alone, and one message of a timed node of the package on its topic, or, where none publishes, a
		clean exit only)«ENDIF», each where installed. (RsaML's own tests run the launch test only on a ROS 2 that has `launch_testing`; on
		the one its CI uses, without it, they compile it and say it was skipped.)

		`gen/`, `test/`, `package.xml`, `CMakeLists.txt`, the launch files and this file are regenerated every time. Yours,
		created once and never overwritten: `src/`, the `.msg` files, each package's `user.cmake`
		(included by its `CMakeLists.txt`; the interfaces package's also lists interface files of your
		own, `.srv`, `.action` or more `.msg`, in `RSAML_USER_INTERFACES`), `config/«pkg».params.yaml` and `«Ros2Manifest.FILE»`
		(version, maintainers, licences, URLs, authors and further dependencies, merged into
		`package.xml`), and `README.md`. Types of other packages used in a generated `.msg` file are found and declared
		when you generate again.
	'''
}
