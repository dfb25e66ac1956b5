/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.Set
import java.util.TreeSet
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxCode
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.ExecutionPlan.LinkPlan
import org.rsaml.analysis.plan.ExecutionPlan.PlannedFunction
import org.rsaml.analysis.plan.ExecutionPlan.PlannedModule
import org.rsaml.analysis.plan.ExecutionPlan.Release
import org.rsaml.generator.spi.GeneratedFile
import org.rsaml.generator.spi.GeneratedProject
import org.rsaml.generator.spi.OutputContext
import org.rsaml.generator.spi.TargetGenerator

/**
 * The ROS 2 target: an ament_cmake package whose nodes (one per module) are rclcpp components of
 * one shared library, each with a publisher per output port and a subscription per entry port on
 * relative topics (connected ports share one), a timer per timed release on the node's clock, the
 * model's times as parameters, subsumption links as extra subscriptions, and launch files for one
 * process or a process per node; plus an interfaces package for the structured message types the
 * model names without a ROS package. The nodes derive from the scheduling runtime (gen/rsaml/, the
 * files runtime/ros2/rsaml/* of this bundle): each timed release on an executor thread of its own at
 * the analysis's real-time priority, in the package's component container or a node's own process.
 * Same generation gap as the C++ target: gen/ and the build
 * files are regenerated; src/, the .msg files, user.cmake and package.user.xml are the architect's.
 */
class Ros2Target implements TargetGenerator {

	override id() {
		"ros2"
	}

	override description() {
		"ament_cmake packages for ROS 2 (rclcpp components): a node per module, topics, launch files"
	}

	override generate(ExecutionPlan plan, OutputContext output) {
		val warnings = <String>newArrayList
		val project = CxxNames.stableProject(plan, output.kept, warnings, "the ROS package, the interfaces package and the C++ namespace")
		val files = new Ros2Files(plan, project, output)
		for (cycle : plan.reactiveCycles) {
			warnings += "modules " + cycle.map[qualifiedName].join(" -> ")
				+ " react to each other's data in a cycle; ROS 2 messages carry no wave, so each of them reacts at most once per "
				+ cycle.map[files.cycleBound(it)].join(", ")
				+ " (the shortest period that feeds the cycle; parameter reaction.min_interval_ns)"
		}
		new GeneratedProject(files.files, warnings, #{CxxNames.KEPT_PROJECT -> project})
	}
}

/** The files of one plan. */
class Ros2Files {

	val ExecutionPlan plan
	val extension CxxNames names
	val extension Ros2Names rosNames
	val OutputContext output
	val String banner
	val String pkg

	new(ExecutionPlan plan, String project, OutputContext output) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.rosNames = new Ros2Names(plan, names)
		this.output = output
		this.pkg = names.project
		this.banner = Templates.banner(plan)
	}

	def cycleBound(PlannedModule m) {
		Ros2Names.duration(rosNames.cycleBoundNs(m))
	}

	def files() {
		val files = <GeneratedFile>newArrayList
		val manifest = manifest(pkg)
		files += GeneratedFile.generated(pkg + "/package.xml", packageXml(manifest))
		files += GeneratedFile.user(pkg + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(pkg))
		files += GeneratedFile.generated(pkg + "/CMakeLists.txt", cmake)
		files += GeneratedFile.user(pkg + "/user.cmake", userCmake)
		files += GeneratedFile.generated(pkg + "/launch/" + pkg + ".launch.py", launchComposed)
		files += GeneratedFile.generated(pkg + "/launch/" + pkg + "_processes.launch.py", launchProcesses)
		for (f : #["scheduling.hpp", "scheduling.cpp", "container.cpp"]) {
			files += GeneratedFile.generated(pkg + "/gen/rsaml/" + f, runtimeFile(f))
		}
		for (m : plan.modules) {
			files += GeneratedFile.generated(pkg + "/gen/" + m.layerId + "/" + m.baseName + ".hpp", base(m))
			files += GeneratedFile.generated(pkg + "/gen/" + m.layerId + "/" + m.className + "Component.cpp", component(m))
			files += GeneratedFile.generated(pkg + "/gen/" + m.layerId + "/" + m.mainName + ".cpp", nodeMain(m))
			files += GeneratedFile.user(pkg + "/src/" + m.layerId + "/" + m.className + ".hpp", userHeader(m), m.hooks, m.stubs, CxxCode.IDENTIFIERS)
			files += GeneratedFile.user(pkg + "/src/" + m.layerId + "/" + m.className + ".cpp", userSource(m))
		}
		if (!generatedMessages.empty) {
			val ipkg = rosNames.interfacesPackage
			val imanifest = manifest(ipkg)
			val deps = new TreeSet<String>
			for (t : generatedMessages) {
				output.userFile(ipkg + "/msg/" + t.rosName + ".msg").ifPresent[deps += Ros2Manifest.messageDependencies(it, ipkg)]
			}
			deps += imanifest.buildDependencies
			deps -= ipkg
			files += GeneratedFile.generated(ipkg + "/package.xml", interfacesPackageXml(imanifest, deps))
			files += GeneratedFile.user(ipkg + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(ipkg))
			files += GeneratedFile.user(ipkg + "/user.cmake", interfacesUserCmake)
			files += GeneratedFile.generated(ipkg + "/CMakeLists.txt", interfacesCmake(deps))
			for (t : generatedMessages) {
				files += GeneratedFile.user(ipkg + "/msg/" + t.rosName + ".msg", '''
					# Message type «Names.comment(t.key)» of architecture '«Names.comment(plan.name)»'.
					# «Templates.USER_OWNED» Declare its fields, for example:
					# float64 x
					# std_msgs/Header header
					# Types of other packages are found when you generate again, and declared as dependencies.
				''')
			}
		}
		files += GeneratedFile.user("README.md", readme)
		files
	}

	/**
	 * A file of the scheduling runtime (runtime/ros2/rsaml/ of this bundle), in the package's
	 * namespace, so that the libraries of two packages can share a process.
	 */
	def private runtimeFile(String file) {
		val in = Ros2Target.getResourceAsStream("/runtime/ros2/rsaml/" + file)
		if (in === null) {
			throw new IllegalStateException("the ROS 2 runtime file " + file + " is missing from org.rsaml.generator")
		}
		val text = try new String(in.readAllBytes, java.nio.charset.StandardCharsets.UTF_8) finally in.close
		"// " + banner + "\n" + text.replace("namespace rsaml_ros2 {", "namespace " + names.project + "::rsaml_ros2 {")
			.replace("}  // namespace rsaml_ros2", "}  // namespace " + names.project + "::rsaml_ros2")
			.replace("rsaml_ros2::Container", names.project + "::rsaml_ros2::Container")
	}

	/** The architect's package.user.xml of a package, or the defaults it starts with. */
	def private manifest(String name) {
		val path = name + "/" + Ros2Manifest.FILE
		val text = output.userFile(path)
		if (text.present) Ros2Manifest.parse(path, text.get) else Ros2Manifest.initial(name)
	}

	def private generatedMessages() {
		rosNames.messages.filter[rosGenerated].toList
	}

	/** ROS packages the nodes use, sorted: std_msgs, the interfaces package, packages named on ports. */
	def private messagePackages() {
		val packages = new TreeSet<String>
		for (m : plan.modules) {
			for (p : m.ports) {
				packages += p.rosPackage
			}
		}
		packages
	}

	def private str(String text) {
		Names.cppString(text)
	}

	def private py(String text) {
		Names.pythonString(text)
	}

	def private doc(String text) {
		Templates.doc(text)
	}

	def private described(String text) {
		Templates.described(text)
	}

	def private people(Ros2Manifest manifest) '''
		«FOR x : manifest.xml("maintainer")»
			«x»
		«ENDFOR»
		«FOR x : manifest.xml("license")»
			«x»
		«ENDFOR»
		«FOR x : manifest.xml("url")»
			«x»
		«ENDFOR»
		«FOR x : manifest.xml("author")»
			«x»
		«ENDFOR»
	'''

	def private packageXml(Ros2Manifest manifest) {
		val description = if (doc(plan.description).empty) "The RsaML architecture " + plan.name else plan.description
		val depends = new TreeSet<String>(#{"rclcpp", "rclcpp_components"})
		depends += messagePackages
		val generated = <String>newHashSet
		generated += "buildtool_depend ament_cmake"
		depends.forEach[generated += "depend " + it]
		#["launch", "launch_ros", "ros2launch"].forEach[generated += "exec_depend " + it]
		'''
			<?xml version="1.0"?>
			<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
			<!-- «Names.xml(banner)» -->
			<!-- Version, maintainers, licences, URLs, authors and further dependencies: «Ros2Manifest.FILE» (yours). -->
			<package format="3">
			  <name>«pkg»</name>
			  <version>«manifest.version»</version>
			  <description>«Names.xml(doc(description))»</description>
			  «people(manifest)»

			  <buildtool_depend>ament_cmake</buildtool_depend>

			  «FOR p : depends»
			  	<depend>«p»</depend>
			  «ENDFOR»

			  <exec_depend>launch</exec_depend>
			  <exec_depend>launch_ros</exec_depend>
			  <exec_depend>ros2launch</exec_depend>
			  «FOR d : manifest.dependencies(generated)»
			  	«d»
			  «ENDFOR»

			  <export>
			    <build_type>ament_cmake</build_type>
			  </export>
			</package>
		'''
	}

	def private interfacesPackageXml(Ros2Manifest manifest, Set<String> deps) {
		val generated = <String>newHashSet
		generated += "buildtool_depend ament_cmake"
		generated += "buildtool_depend rosidl_default_generators"
		generated += "exec_depend rosidl_default_runtime"
		deps.forEach[generated += "depend " + it]
		'''
			<?xml version="1.0"?>
			<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
			<!-- «Names.xml(banner)» -->
			<!-- Version, maintainers, licences, URLs, authors and further dependencies: «Ros2Manifest.FILE» (yours). -->
			<package format="3">
			  <name>«rosNames.interfacesPackage»</name>
			  <version>«manifest.version»</version>
			  <description>«Names.xml("Message types of the RsaML architecture " + doc(plan.name))»</description>
			  «people(manifest)»

			  <buildtool_depend>ament_cmake</buildtool_depend>
			  <buildtool_depend>rosidl_default_generators</buildtool_depend>
			  «FOR d : deps»
			  	<depend>«d»</depend>
			  «ENDFOR»
			  <exec_depend>rosidl_default_runtime</exec_depend>
			  «FOR d : manifest.dependencies(generated)»
			  	«d»
			  «ENDFOR»
			  <member_of_group>rosidl_interface_packages</member_of_group>

			  <export>
			    <build_type>ament_cmake</build_type>
			  </export>
			</package>
		'''
	}

	def private interfacesCmake(Set<String> deps) '''
		# «banner»
		# Message packages your .msg files use are found when you generate again; others you need go in
		# «Ros2Manifest.FILE» as <depend>. Interface files of your own (srv/, action/, more msg/) go in
		# user.cmake, included below.
		cmake_minimum_required(VERSION 3.8)
		project(«rosNames.interfacesPackage»)

		find_package(ament_cmake REQUIRED)
		find_package(rosidl_default_generators REQUIRED)
		«FOR d : deps»
			find_package(«d» REQUIRED)
		«ENDFOR»

		set(RSAML_USER_INTERFACES "")
		include(${CMAKE_CURRENT_SOURCE_DIR}/user.cmake)

		rosidl_generate_interfaces(${PROJECT_NAME}
		  «FOR t : generatedMessages»
		  	"msg/«t.rosName».msg"
		  «ENDFOR»
		  ${RSAML_USER_INTERFACES}
		  «IF !deps.empty»
		  	DEPENDENCIES «deps.join(" ")»
		  «ENDIF»
		)

		ament_export_dependencies(rosidl_default_runtime)
		ament_package()
	'''

	def private cmake() '''
		# «banner»
		# Every node is an rclcpp component of the shared library ${PROJECT_NAME}, and an executable of
		# its own. Your additions go in user.cmake, included below.
		cmake_minimum_required(VERSION 3.8)
		project(«pkg» LANGUAGES CXX)

		if(NOT CMAKE_CXX_STANDARD)
		  set(CMAKE_CXX_STANDARD 17)
		  set(CMAKE_CXX_STANDARD_REQUIRED ON)
		endif()

		find_package(ament_cmake REQUIRED)
		find_package(rclcpp REQUIRED)
		find_package(rclcpp_components REQUIRED)
		find_package(Threads REQUIRED)
		«FOR p : messagePackages»
			find_package(«p» REQUIRED)
		«ENDFOR»

		add_library(${PROJECT_NAME} SHARED
		  gen/rsaml/scheduling.cpp
		  «FOR m : plan.modules»
		  	gen/«m.layerId»/«m.className»Component.cpp
		  	src/«m.layerId»/«m.className».cpp
		  «ENDFOR»
		)
		target_include_directories(${PROJECT_NAME} PUBLIC gen src)
		target_link_libraries(${PROJECT_NAME} PUBLIC rclcpp::rclcpp Threads::Threads«FOR p : messagePackages» ${«p»_TARGETS}«ENDFOR» PRIVATE rclcpp_components::component)
		rclcpp_components_register_nodes(${PROJECT_NAME}
		  «FOR m : plan.modules»
		  	"«plugin(m)»"
		  «ENDFOR»
		)

		# The component container of the launch file: each timed release on a thread at its priority.
		add_executable(«rosNames.containerExecutable» gen/rsaml/container.cpp)
		target_link_libraries(«rosNames.containerExecutable» PRIVATE ${PROJECT_NAME} rclcpp_components::component_manager)

		# An executable per node, scheduled as in the container.
		«FOR m : plan.modules»
			add_executable(«m.executable» gen/«m.layerId»/«m.mainName».cpp)
			target_link_libraries(«m.executable» PRIVATE ${PROJECT_NAME})
		«ENDFOR»

		include(user.cmake)

		install(TARGETS ${PROJECT_NAME} ARCHIVE DESTINATION lib LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
		install(TARGETS «rosNames.containerExecutable»«FOR m : plan.modules» «m.executable»«ENDFOR» DESTINATION lib/${PROJECT_NAME})
		install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})

		ament_package()
	'''

	def private interfacesUserCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# rosidl_generate_interfaces(). Your own interface files, for example:
		#   list(APPEND RSAML_USER_INTERFACES "srv/SetSpeed.srv" "action/Move.action")
		# Packages their fields use go in «Ros2Manifest.FILE» (<depend>geometry_msgs</depend>).
	'''

	def private userCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# ament_package(). The nodes are the shared library ${PROJECT_NAME}; add what they need, e.g.
		#   find_package(tf2_ros REQUIRED)
		#   target_link_libraries(${PROJECT_NAME} PRIVATE tf2_ros::tf2_ros)
		# and name the package in «Ros2Manifest.FILE» (<depend>tf2_ros</depend>).
	'''

	def private plugin(PlannedModule m) {
		names.project + "::" + m.layerId + "::" + m.className
	}

	def private launchArguments() '''
		DeclareLaunchArgument('namespace', default_value='',
		                      description='Namespace of every node and topic (a second robot: another namespace)'),
		DeclareLaunchArgument('use_sim_time', default_value='false',
		                      description='Run the nodes on the simulation clock (/clock)'),
		DeclareLaunchArgument('simulated_load', default_value='0.0',
		                      description='Busy work of every timed job, as a fraction (0 to 1) of its modeled execution time'),
	'''

	def private launchComposed() '''
		# «banner»
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
		# namespace:=NS (all nodes and topics under NS), use_sim_time:=true, simulated_load:=0.9 (every
		# timed job busy-works 90 % of its modeled execution time).
		from launch import LaunchDescription
		from launch.actions import DeclareLaunchArgument
		from launch.substitutions import LaunchConfiguration
		from launch_ros.actions import ComposableNodeContainer
		from launch_ros.descriptions import ComposableNode
		from launch_ros.parameter_descriptions import ParameterValue


		def generate_launch_description():
		    namespace = LaunchConfiguration('namespace')
		    parameters = [{'use_sim_time': LaunchConfiguration('use_sim_time'),
		                   'rsaml.simulated_load': ParameterValue(LaunchConfiguration('simulated_load'), value_type=float)}]
		    return LaunchDescription([
		        «launchArguments»
		        «FOR c : rosNames.containers»
		        	«IF c.processor !== null»
		        	# Processor '«Names.comment(c.processor.name)»'«IF c.core >= 0»: CPU core «c.core»«ENDIF».
		        	«ELSEIF rosNames.containers.size > 1»
		        	# The modules no processor names.
		        	«ENDIF»
		        	ComposableNodeContainer(
		        	    name=«py(c.name)», namespace=namespace, package=«py(pkg)»,
		        	    executable=«py(rosNames.containerExecutable)», output='screen', parameters=parameters,«IF c.core >= 0»
		        	    prefix=«py(taskset(c.core))»,«ENDIF»
		        	    composable_node_descriptions=[
		        	        «FOR m : c.modules»
		        	        	ComposableNode(package=«py(pkg)», plugin=«py(plugin(m))», name=«py(m.rosNode)»,
		        	        	               namespace=namespace, parameters=parameters),
		        	        «ENDFOR»
		        	    ]),
		        «ENDFOR»
		    ])
	'''

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

	def private launchProcesses() '''
		# «banner»
		# Starts every module of the architecture as a node in a process of its own«IF rosNames.containers.exists[core >= 0]», pinned with
		# taskset to the core of its processor where the model names one«ENDIF». Arguments:
		# namespace:=NS (all nodes and topics under NS), use_sim_time:=true, simulated_load:=0.9 (every
		# timed job busy-works 90 % of its modeled execution time).
		from launch import LaunchDescription
		from launch.actions import DeclareLaunchArgument
		from launch.substitutions import LaunchConfiguration
		from launch_ros.actions import Node
		from launch_ros.parameter_descriptions import ParameterValue


		def generate_launch_description():
		    namespace = LaunchConfiguration('namespace')
		    parameters = [{'use_sim_time': LaunchConfiguration('use_sim_time'),
		                   'rsaml.simulated_load': ParameterValue(LaunchConfiguration('simulated_load'), value_type=float)}]
		    return LaunchDescription([
		        «launchArguments»
		        «FOR m : plan.modules»
		        	Node(package=«py(pkg)», executable=«py(m.executable)», name=«py(m.rosNode)»,
		        	     namespace=namespace, parameters=parameters, output='screen'«IF m.core >= 0»,
		        	     prefix=«py(taskset(m.core))»«ENDIF»),
		        «ENDFOR»
		    ])
	'''

	def private headersOf(PlannedModule m) {
		val headers = new TreeSet<String>
		for (p : m.ports) {
			headers += p.rosHeader
		}
		for (p : m.inputs) {
			for (l : p.suppressors) {
				headers += l.trigger.rosHeader
			}
		}
		for (p : m.outputs) {
			for (l : p.inhibitors) {
				headers += l.trigger.rosHeader
			}
		}
		headers
	}

	/** Links whose state lives in this module's node: suppressors of its inputs, inhibitors of its outputs. */
	def private linksOf(PlannedModule m) {
		val links = <LinkPlan>newArrayList
		m.inputs.forEach[links += suppressors]
		m.outputs.forEach[links += inhibitors]
		links
	}

	/** The parameter holding a release's period. */
	def private periodParameter(Release r) {
		r.method.replaceFirst("^release_", "") + ".period_ns"
	}

	def private base(PlannedModule m) '''
		// «banner»
		#pragma once

		#include <cstdint>
		#include <memory>
		#include <optional>
		#include <stdexcept>
		#include <string>

		#include <rclcpp/rclcpp.hpp>
		#include "rsaml/scheduling.hpp"
		«FOR h : headersOf(m)»
			#include <«h»>
		«ENDFOR»

		namespace «names.project»::«m.layerId» {

		/**
		 * Node «doc(m.rosNode)»: module «doc(m.qualifiedName)»«described(m.description)»
		 * Timing: «doc(m.timing)».
		 * The generated part: «m.className» (src/«m.layerId»/«m.className».hpp, yours) derives from it.
		 * Topics are relative: the node's namespace (launch argument namespace) prefixes them all. The
		 * model's times are parameters (nanoseconds, > 0) with the model's values as defaults; QoS can be
		 * overridden with the qos_overrides.<topic> parameters; timers run on the node's clock
		 * (use_sim_time).
		 */
		class «m.baseName» : public ::«names.project»::rsaml_ros2::ScheduledNode {
		 public:
		  explicit «m.baseName»(const rclcpp::NodeOptions& options)
		      : ::«names.project»::rsaml_ros2::ScheduledNode(«str(m.rosNode)», options, «str(m.qualifiedName)», «m.core») {
		    «FOR r : m.releases»
		    	«r.timerMember»_period_ = positive(«str(r.periodParameter)», this->declare_parameter<std::int64_t>(«str(r.periodParameter)», «r.periodNs»));
		    «ENDFOR»
		    «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		    	«f.lastRunMember»_interval_ = positive(«str(f.method + ".min_interval_ns")», this->declare_parameter<std::int64_t>(«str(f.method + ".min_interval_ns")», «f.minIntervalNs»));
		    «ENDFOR»
		    «IF m.reactive && m.reactionIntervalNs > 0»
		    	reaction_interval_ = positive("reaction.min_interval_ns", this->declare_parameter<std::int64_t>("reaction.min_interval_ns", «m.reactionIntervalNs»));
		    «ENDIF»
		    «FOR l : linksOf(m)»
		    	link_«l.stem»_duration_ = positive(«str(l.stem + ".duration_ns")», this->declare_parameter<std::int64_t>(«str(l.stem + ".duration_ns")», «l.durationNs»));
		    «ENDFOR»
		    rclcpp::PublisherOptions publisher_options;
		    publisher_options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();
		    rclcpp::SubscriptionOptions subscription_options;
		    subscription_options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();
		    (void)publisher_options;
		    (void)subscription_options;
		    «FOR p : m.outputs»
		    	«p.pubName»_ = this->create_publisher<«p.rosType»>(«str(p.topic)», «p.qos», publisher_options);
		    «ENDFOR»
		    «FOR p : m.inputs»
		    	«p.subName»_ = this->create_subscription<«p.rosType»>(
		    	    «str(p.topic)», «p.qos»,
		    	    [this, port = this->rsaml_add_arrivals(«str(p.name)»)](std::shared_ptr<const «p.rosType»> message) {
		    	      this->rsaml_run_arrival(port, [&] { this->«p.receiveName»(*message, false); });
		    	    },
		    	    subscription_options);
		    «ENDFOR»
		    «FOR l : linksOf(m)»
		    	// «IF l.inhibitor»Inhibitor«ELSE»Suppressor«ENDIF» «doc(l.qualifiedName)», triggered by «IF l.trigger.assertsOnlyWhenTrue»each true on «ELSE»each message on «ENDIF»«doc(l.trigger.qualifiedName)».
		    	link_«l.stem»_sub_ = this->create_subscription<«l.trigger.rosType»>(
		    	    «str(l.trigger.topic)», «l.trigger.qos»,
		    	    [this, port = this->rsaml_add_arrivals(«str(l.qualifiedName)»)](std::shared_ptr<const «l.trigger.rosType»> message) {
		    	      this->rsaml_run_arrival(port, [&] {
		    	        «IF l.trigger.assertsOnlyWhenTrue»
		    	        	if (!message->data) {
		    	        	  return;  // only true asserts the link: false neither starts nor ends it, nor is delivered
		    	        	}
		    	        «ENDIF»
		    	        link_«l.stem»_until_ = this->now() + rclcpp::Duration::from_nanoseconds(link_«l.stem»_duration_);
		    	        «IF l.deliversData»
		    	        	this->«l.target.receiveName»(*message, true);
		    	        «ELSE»
		    	        	(void)message;
		    	        «ENDIF»
		    	      });
		    	    },
		    	    subscription_options);
		    «ENDFOR»
		    «FOR r : m.releases»
		    	// «r.kind.name.toLowerCase» «doc(r.label)» every «r.periodNs» ns («r.why»): rank «r.rank», deadline «r.deadlineNs» ns, cost «r.costNs» ns
		    	«r.timerMember»_ = this->rsaml_add_timer(
		    	    this->rsaml_add_release(«str(r.label)», «r.rank», «IF r.policy == org.rsaml.model.SchedulingPolicy.RR»true«ELSE»false«ENDIF», «r.deadlineNs», «r.costNs»),
		    	    «r.timerMember»_period_, [this] { this->«r.method»(); });
		    «ENDFOR»
		  }
		  «IF !m.inputs.empty»

		  	// Entry ports: the latest message received.
		  	«FOR p : m.inputs»
		  		«p.rosType» «p.inName»;
		  	«ENDFOR»
		  «ENDIF»
		  «IF !m.outputs.empty»

		  	// Output ports: set them; they are published after each activation (or call publish_outputs()).
		  	«FOR p : m.outputs»
		  		«p.rosType» «p.outName»;
		  	«ENDFOR»
		  «ENDIF»

		 protected:
		  «FOR f : m.functions»
		  	/** Function «doc(f.name)» («doc(f.timing)») */
		  	virtual void «f.method»() {
		  	  «FOR a : f.inlineActions»
		  	  	«a.method»();
		  	  «ENDFOR»
		  	}
		  	«FOR a : f.actions»
		  		/** Action «doc(a.name)» («doc(a.timing)») */
		  		virtual void «a.method»() {}
		  	«ENDFOR»
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	/** Called on each message at «doc(p.name)», before the node reacts. */
		  	virtual void «p.onName»(const «p.rosType»& message) { (void)message; }
		  «ENDFOR»
		  /** Publishes every output port (unless an inhibitor blocks it). */
		  virtual void publish_outputs() {
		    «FOR p : m.outputs»
		    	«IF p.inhibitors.empty»
		    		«p.pubName»_->publish(«p.outName»);
		    	«ELSE»
		    		if («FOR l : p.inhibitors SEPARATOR ' && '»!active(link_«l.stem»_until_)«ENDFOR») {
		    		  «p.pubName»_->publish(«p.outName»);
		    		}
		    	«ENDIF»
		    «ENDFOR»
		  }

		 private:
		  static std::int64_t positive(const char* parameter, std::int64_t value) {
		    if (value <= 0) {
		      throw std::invalid_argument(std::string("parameter ") + parameter + " must be a positive number of nanoseconds");
		    }
		    return value;
		  }

		  /** Whether a subsumption link is active now (on the node's clock). */
		  bool active(const std::optional<rclcpp::Time>& until) { return until && this->now() < *until; }

		  /** Whether `interval` has passed since `last` (on the node's clock); if so, `last` becomes now. */
		  bool due(std::optional<rclcpp::Time>& last, std::int64_t interval) {
		    const rclcpp::Time now = this->now();
		    if (last && now - *last < rclcpp::Duration::from_nanoseconds(interval)) {
		      return false;
		    }
		    last = now;
		    return true;
		  }
		  «FOR r : m.releases»

		  	void «r.method»() {
		  	  «release(r)»
		  	  publish_outputs();
		  	}
		  «ENDFOR»
		  «FOR p : m.inputs»

		  	void «p.receiveName»(const «p.rosType»& message, bool replacing) {
		  	  «IF !p.suppressors.empty»
		  	  	if (!replacing && («FOR l : p.suppressors SEPARATOR ' || '»active(link_«l.stem»_until_)«ENDFOR»)) {
		  	  	  return;  // suppressed
		  	  	}
		  	  «ELSE»
		  	  	(void)replacing;
		  	  «ENDIF»
		  	  «p.inName» = message;
		  	  «p.onName»(message);
		  	  «IF m.reactive»
		  	  	«m.reactMethod»();
		  	  «ENDIF»
		  	}
		  «ENDFOR»
		  «IF m.reactive»

		  	void «m.reactMethod»() {
		  	  «IF m.reactionIntervalNs > 0»
		  	  	if (!due(last_reaction_, reaction_interval_)) {
		  	  	  return;  // «IF m.cycleBoundNs > 0»at most once per wave of the cycle«ELSE»sporadic: not sooner than its period«ENDIF»
		  	  	}
		  	  «ENDIF»
		  	  «FOR f : m.stepFunctions»
		  	  	«callFunction(f)»
		  	  «ENDFOR»
		  	  publish_outputs();
		  	}
		  «ENDIF»

		  «FOR r : m.releases»
		  	std::int64_t «r.timerMember»_period_;
		  «ENDFOR»
		  «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		  	std::int64_t «f.lastRunMember»_interval_;
		  	std::optional<rclcpp::Time> «f.lastRunMember»;
		  «ENDFOR»
		  «IF m.reactive && m.reactionIntervalNs > 0»
		  	std::int64_t reaction_interval_;
		  	std::optional<rclcpp::Time> last_reaction_;
		  «ENDIF»
		  «FOR p : m.outputs»
		  	rclcpp::Publisher<«p.rosType»>::SharedPtr «p.pubName»_;
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	rclcpp::Subscription<«p.rosType»>::SharedPtr «p.subName»_;
		  «ENDFOR»
		  «FOR l : linksOf(m)»
		  	rclcpp::Subscription<«l.trigger.rosType»>::SharedPtr link_«l.stem»_sub_;
		  	std::int64_t link_«l.stem»_duration_;
		  	std::optional<rclcpp::Time> link_«l.stem»_until_;
		  «ENDFOR»
		  «FOR r : m.releases»
		  	rclcpp::TimerBase::SharedPtr «r.timerMember»_;
		  «ENDFOR»
		};

		}  // namespace «names.project»::«m.layerId»
	'''

	def private release(Release r) {
		switch (r.kind) {
			case FUNCTION: '''«r.function.method»();'''
			case ACTION: '''«r.action.method»();'''
			default: '''
				«FOR f : r.module.stepFunctions»
					«callFunction(f)»
				«ENDFOR»
			'''
		}
	}

	def private callFunction(PlannedFunction f) '''
		«IF f.minIntervalNs > 0»
			if (due(«f.lastRunMember», «f.lastRunMember»_interval_)) {
			  «f.method»();
			}
		«ELSE»
			«f.method»();
		«ENDIF»
	'''

	def private component(PlannedModule m) '''
		// «banner»
		// Registers node «doc(m.rosNode)» as the rclcpp component «plugin(m)».
		#include <rclcpp_components/register_node_macro.hpp>

		#include "«m.layerId»/«m.className».hpp"

		RCLCPP_COMPONENTS_REGISTER_NODE(«plugin(m)»)
	'''

	def private nodeMain(PlannedModule m) '''
		// «banner»
		// Executable «m.executable»: node «doc(m.rosNode)» in a process of its own, each timed release on an
		// executor thread of its own at its real-time priority (rsaml/scheduling.hpp).
		#include "«m.layerId»/«m.className».hpp"

		int main(int argc, char** argv) {
		  return ::«names.project»::rsaml_ros2::run_standalone<«plugin(m)»>(argc, argv);
		}
	'''

	def private userHeader(PlannedModule m) '''
		// Node for module «doc(m.qualifiedName)»«described(m.description)»
		// «Templates.USER_OWNED» The generated base class («m.baseName», in
		// gen/«m.layerId»/) creates the publishers, subscriptions and timers; implement the actions and
		// message handlers here. Each is marked override: when the model drops or renames one, the
		// compiler says so instead of silently no longer calling it.
		#pragma once

		#include "«m.layerId»/«m.baseName».hpp"

		namespace «names.project»::«m.layerId» {

		class «m.className» : public «m.baseName» {
		 public:
		  using «m.baseName»::«m.baseName»;

		 protected:
		  «FOR f : m.functions.filter[!actions.empty]»
		  	// Function «doc(f.name)»
		  	«FOR a : f.actions»
		  		void «a.method»() override;
		  	«ENDFOR»
		  «ENDFOR»
		  «IF !m.inputs.empty»
		  	// Entry ports
		  	«FOR p : m.inputs»
		  		void «p.onName»(const «p.rosType»& message) override;
		  	«ENDFOR»
		  «ENDIF»
		};

		}  // namespace «names.project»::«m.layerId»
	'''

	def private userSource(PlannedModule m) '''
		// Node for module «doc(m.qualifiedName)». «Templates.USER_OWNED»
		// Inputs: in_<port> is the latest message. Outputs: set out_<port>; it is published after each
		// activation of the node.
		#include "«m.layerId»/«m.className».hpp"

		namespace «names.project»::«m.layerId» {
		«FOR a : m.actions»

			// «doc(a.function.name)».«doc(a.name)»«described(a.description)»
			void «m.className»::«a.method»() {}
		«ENDFOR»
		«FOR p : m.inputs»

			// «doc(p.name)»«described(p.description)»
			void «m.className»::«p.onName»(const «p.rosType»& message) { (void)message; }
		«ENDFOR»

		}  // namespace «names.project»::«m.layerId»
	'''

	def private readme() '''
		# «doc(plan.name)» for ROS 2

		ament_cmake packages of the RsaML architecture '«doc(plan.name)»', created by
		`rsaml generate --target ros2`, for ROS 2 Humble, Jazzy, Kilted and Rolling: a node per module,
		each an rclcpp component of the library `«pkg»` and an executable of its own, a timer per
		periodic function, a topic per group of connected ports. Put this directory in a colcon
		workspace's `src/`, then:

		```sh
		colcon build
		source install/setup.bash
		ros2 launch «pkg» «pkg».launch.py                  # «IF rosNames.containers.size > 1»a process (component container) per processor«ELSE»all nodes in one process«ENDIF»
		ros2 launch «pkg» «pkg»_processes.launch.py        # a process per node
		ros2 launch «pkg» «pkg».launch.py namespace:=robot2 use_sim_time:=true
		```

		Topics are relative, so `namespace:=...` isolates a second robot. The model's periods, minimum
		intervals and inhibitor/suppressor durations are node parameters (nanoseconds) with the model's
		values as defaults; timers run on the node's clock, so `use_sim_time` works. Topics written by
		modules that read sensors use the sensor data QoS (best effort), the others are reliable; both
		can be overridden with `qos_overrides.<topic>.publisher|subscription.<policy>` parameters.
		«IF rosNames.containers.exists[processor !== null]»

		The model's deployment is kept: «pkg».launch.py starts one component container per processor,
		«FOR c : rosNames.containers SEPARATOR ", "»`«c.name»` («IF c.processor === null»the modules no processor names«ELSE»processor '«doc(c.processor.name)»'«IF c.core >= 0», core «c.core»«ENDIF»«ENDIF»)«ENDFOR».
		Processes of a processor with a core are started under `taskset -c CORE` (util-linux), in both
		launch files; on a machine without that core they start unpinned and say so.
		«ENDIF»

		The nodes are scheduled as `rsaml analyze` assumes: in the container `«rosNames.containerExecutable»`
		(and in each node's own executable) every timed release has a callback group of its own, served
		by a single-threaded executor on a thread of its own under `SCHED_FIFO` (`SCHED_RR` for round
		robin) at the analysis's rank, pinned to its processor's core; data arrivals and ROS 2's services
		run on the process's main executor at the default priority, and a node's activations hold its
		lock, so they never run at once. Where real-time priorities are not permitted (neither root nor
		`CAP_SYS_NICE` nor an `rtprio` limit), each release thread says so on standard output and runs at
		the default priority: then the analysis's verdicts do not hold. Every node measures its jobs
		(release to completion, on the node's clock), prints `miss` and `overrun` lines as they happen
		and a `summary` line per release and per entry port at exit. The parameter
		`rsaml.simulated_load:=0.9` makes every job busy-work 90 % of its modeled execution time, to see
		the timing before the code is written.

		`gen/`, `package.xml`, `CMakeLists.txt` and the launch files are regenerated every time. Yours,
		created once and never overwritten: `src/`, the `.msg` files, each package's `user.cmake`
		(included by its `CMakeLists.txt`; the interfaces package's also lists interface files of your
		own, `.srv`, `.action` or more `.msg`, in `RSAML_USER_INTERFACES`) and `«Ros2Manifest.FILE»`
		(version, maintainers, licences, URLs, authors and further dependencies, merged into
		`package.xml`). Types of other packages used in a generated `.msg` file are found and declared
		when you generate again.
	'''
}
