/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxCode
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.plan.ExecutionPlan
import org.rsaml.generator.plan.ExecutionPlan.LinkPlan
import org.rsaml.generator.plan.ExecutionPlan.PlannedFunction
import org.rsaml.generator.plan.ExecutionPlan.PlannedModule
import org.rsaml.generator.plan.ExecutionPlan.Release
import org.rsaml.generator.spi.GeneratedFile
import org.rsaml.generator.spi.GeneratedProject
import org.rsaml.generator.spi.OutputContext
import org.rsaml.generator.spi.TargetGenerator

/**
 * The ROS 2 target: an ament_cmake package with a node (rclcpp) per module, namespaced by layer,
 * a timer per timed release, a publisher per output port and a subscription per entry port
 * (connected ports share one topic), subsumption links as extra subscriptions, and a Python launch
 * file for the whole architecture; plus an interfaces package for the structured message types the
 * model names without a ROS package. Same generation gap as the C++ target: gen/ is regenerated,
 * src/ and the .msg files are the architect's.
 */
class Ros2Target implements TargetGenerator {

	override id() {
		"ros2"
	}

	override description() {
		"ament_cmake packages for ROS 2 (rclcpp): a node per module, topics, a launch file"
	}

	override generate(ExecutionPlan plan, OutputContext output) {
		val warnings = <String>newArrayList
		val project = CxxNames.stableProject(plan, output.kept, warnings, "the ROS package, the interfaces package and the C++ namespace")
		for (cycle : plan.reactiveCycles) {
			warnings += "modules " + cycle.map[qualifiedName].join(" -> ")
				+ " react to each other's data in a cycle: in ROS 2 each message goes round again; make one of them periodic or sporadic"
		}
		new GeneratedProject(new Ros2Files(plan, project).files, warnings, #{CxxNames.KEPT_PROJECT -> project})
	}
}

/** The files of one plan. */
class Ros2Files {

	val ExecutionPlan plan
	val extension CxxNames names
	val extension Ros2Names rosNames
	val String banner
	val String pkg

	new(ExecutionPlan plan, String project) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.rosNames = new Ros2Names(plan, names)
		this.pkg = names.project
		this.banner = Templates.banner(plan)
	}

	def files() {
		val files = <GeneratedFile>newArrayList
		files += GeneratedFile.generated(pkg + "/package.xml", packageXml)
		files += GeneratedFile.generated(pkg + "/CMakeLists.txt", cmake)
		files += GeneratedFile.generated(pkg + "/launch/" + pkg + ".launch.py", launch)
		for (m : plan.modules) {
			files += GeneratedFile.generated(pkg + "/gen/" + m.layerId + "/" + m.baseName + ".hpp", base(m))
			files += GeneratedFile.generated(pkg + "/gen/" + m.layerId + "/" + m.mainName + ".cpp", main(m))
			files += GeneratedFile.user(pkg + "/src/" + m.layerId + "/" + m.className + ".hpp", userHeader(m), m.hooks, m.stubs, CxxCode.IDENTIFIERS)
			files += GeneratedFile.user(pkg + "/src/" + m.layerId + "/" + m.className + ".cpp", userSource(m))
		}
		if (!generatedMessages.empty) {
			val ipkg = rosNames.interfacesPackage
			files += GeneratedFile.generated(ipkg + "/package.xml", interfacesPackageXml)
			files += GeneratedFile.generated(ipkg + "/CMakeLists.txt", interfacesCmake)
			for (t : generatedMessages) {
				files += GeneratedFile.user(ipkg + "/msg/" + t.rosName + ".msg", '''
					# Message type «Names.comment(t.key)» of architecture '«Names.comment(plan.name)»'.
					# «Templates.USER_OWNED» Declare its fields, for example:
					# float64 x
				''')
			}
		}
		files += GeneratedFile.user("README.md", readme)
		files
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

	def private doc(String text) {
		Templates.doc(text)
	}

	def private described(String text) {
		Templates.described(text)
	}

	def private packageXml() {
		val description = if (doc(plan.description).empty) "The RsaML architecture " + plan.name else plan.description
		'''
			<?xml version="1.0"?>
			<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
			<!-- «Names.xml(banner)» -->
			<package format="3">
			  <name>«pkg»</name>
			  <version>0.1.0</version>
			  <description>«Names.xml(doc(description))»</description>
			  <maintainer email="maintainer@example.com">Maintainer</maintainer>
			  <license>TODO</license>

			  <buildtool_depend>ament_cmake</buildtool_depend>

			  <depend>rclcpp</depend>
			  «FOR p : messagePackages»
			  	<depend>«p»</depend>
			  «ENDFOR»

			  <exec_depend>launch</exec_depend>
			  <exec_depend>launch_ros</exec_depend>

			  <export>
			    <build_type>ament_cmake</build_type>
			  </export>
			</package>
		'''
	}

	def private interfacesPackageXml() '''
		<?xml version="1.0"?>
		<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
		<!-- «Names.xml(banner)» -->
		<package format="3">
		  <name>«rosNames.interfacesPackage»</name>
		  <version>0.1.0</version>
		  <description>«Names.xml("Message types of the RsaML architecture " + doc(plan.name))»</description>
		  <maintainer email="maintainer@example.com">Maintainer</maintainer>
		  <license>TODO</license>

		  <buildtool_depend>ament_cmake</buildtool_depend>
		  <buildtool_depend>rosidl_default_generators</buildtool_depend>
		  <exec_depend>rosidl_default_runtime</exec_depend>
		  <member_of_group>rosidl_interface_packages</member_of_group>

		  <export>
		    <build_type>ament_cmake</build_type>
		  </export>
		</package>
	'''

	def private interfacesCmake() '''
		# «banner»
		cmake_minimum_required(VERSION 3.8)
		project(«rosNames.interfacesPackage»)

		find_package(ament_cmake REQUIRED)
		find_package(rosidl_default_generators REQUIRED)

		rosidl_generate_interfaces(${PROJECT_NAME}
		  «FOR t : generatedMessages»
		  	"msg/«t.rosName».msg"
		  «ENDFOR»
		)

		ament_export_dependencies(rosidl_default_runtime)
		ament_package()
	'''

	def private cmake() '''
		# «banner»
		cmake_minimum_required(VERSION 3.8)
		project(«pkg» LANGUAGES CXX)

		if(NOT CMAKE_CXX_STANDARD)
		  set(CMAKE_CXX_STANDARD 17)
		  set(CMAKE_CXX_STANDARD_REQUIRED ON)
		endif()

		find_package(ament_cmake REQUIRED)
		find_package(rclcpp REQUIRED)
		«FOR p : messagePackages»
			find_package(«p» REQUIRED)
		«ENDFOR»

		«FOR m : plan.modules»
			# Node «doc(m.qualifiedName)»
			add_executable(«m.executable» gen/«m.layerId»/«m.mainName».cpp src/«m.layerId»/«m.className».cpp)
			target_include_directories(«m.executable» PRIVATE gen src)
			ament_target_dependencies(«m.executable» rclcpp«FOR p : messagePackages» «p»«ENDFOR»)

		«ENDFOR»
		install(TARGETS
		  «FOR m : plan.modules»
		  	«m.executable»
		  «ENDFOR»
		  DESTINATION lib/${PROJECT_NAME})
		install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})

		ament_package()
	'''

	def private launch() '''
		# «banner»
		# Starts every module of the architecture as a node, its layer as the namespace.
		from launch import LaunchDescription
		from launch_ros.actions import Node


		def generate_launch_description():
		    return LaunchDescription([
		        «FOR m : plan.modules»
		        	Node(package=«Names.pythonString(pkg)», executable=«Names.pythonString(m.executable)», name=«Names.pythonString(m.nodeName)»,
		        	     namespace=«Names.pythonString(m.layerId)», output='screen'),
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

	def private base(PlannedModule m) '''
		// «banner»
		#pragma once

		#include <chrono>
		#include <memory>

		#include <rclcpp/rclcpp.hpp>
		«FOR h : headersOf(m)»
			#include <«h»>
		«ENDFOR»

		namespace «names.project»::«m.layerId» {

		/**
		 * Node «doc(m.nodeName)» in namespace /«m.layerId»: module «doc(m.qualifiedName)»«described(m.description)»
		 * Timing: «doc(m.timing)».
		 * The generated part: «m.className» (src/«m.layerId»/«m.className».hpp, yours) derives from it.
		 */
		class «m.baseName» : public rclcpp::Node {
		 public:
		  explicit «m.baseName»(const rclcpp::NodeOptions& options = rclcpp::NodeOptions())
		      : rclcpp::Node(«str(m.nodeName)», «str("/" + m.layerId)», options) {
		    «FOR p : m.outputs»
		    	«p.pubName»_ = this->create_publisher<«p.rosType»>(«str(p.topic)», rclcpp::QoS(10));
		    «ENDFOR»
		    «FOR p : m.inputs»
		    	«p.subName»_ = this->create_subscription<«p.rosType»>(
		    	    «str(p.topic)», rclcpp::QoS(10),
		    	    [this](std::shared_ptr<const «p.rosType»> message) { «p.receiveName»(*message, false); });
		    «ENDFOR»
		    «FOR l : linksOf(m)»
		    	// «IF l.inhibitor»Inhibitor«ELSE»Suppressor«ENDIF» «doc(l.qualifiedName)», triggered by «doc(l.trigger.qualifiedName)».
		    	link_«l.stem»_sub_ = this->create_subscription<«l.trigger.rosType»>(
		    	    «str(l.trigger.topic)», rclcpp::QoS(10),
		    	    [this](std::shared_ptr<const «l.trigger.rosType»> message) {
		    	      link_«l.stem»_until_ = std::chrono::steady_clock::now() + std::chrono::nanoseconds(«l.durationNs»);
		    	      «IF l.deliversData»
		    	      	«l.target.receiveName»(*message, true);
		    	      «ELSE»
		    	      	(void)message;
		    	      «ENDIF»
		    	    });
		    «ENDFOR»
		    «FOR r : m.releases»
		    	// «r.kind.name.toLowerCase» «doc(r.label)» every «r.periodNs» ns («r.why»)
		    	«r.timerMember»_ = this->create_wall_timer(std::chrono::nanoseconds(«r.periodNs»), [this] { «r.method»(); });
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
		    		if («FOR l : p.inhibitors SEPARATOR ' && '»std::chrono::steady_clock::now() >= link_«l.stem»_until_«ENDFOR») {
		    		  «p.pubName»_->publish(«p.outName»);
		    		}
		    	«ENDIF»
		    «ENDFOR»
		  }

		 private:
		  «FOR r : m.releases»
		  	void «r.method»() {
		  	  «release(r)»
		  	  publish_outputs();
		  	}
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	void «p.receiveName»(const «p.rosType»& message, bool replacing) {
		  	  «IF !p.suppressors.empty»
		  	  	if (!replacing && !(«FOR l : p.suppressors SEPARATOR ' && '»std::chrono::steady_clock::now() >= link_«l.stem»_until_«ENDFOR»)) {
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
		  	  «IF m.minIntervalNs > 0»
		  	  	const auto now = std::chrono::steady_clock::now();
		  	  	if (reacted_ && now - last_reaction_ < std::chrono::nanoseconds(«m.minIntervalNs»)) {
		  	  	  return;  // sporadic: not sooner than its period
		  	  	}
		  	  	reacted_ = true;
		  	  	last_reaction_ = now;
		  	  «ENDIF»
		  	  «FOR f : m.stepFunctions»
		  	  	«callFunction(f)»
		  	  «ENDFOR»
		  	  publish_outputs();
		  	}
		  «ENDIF»
		  «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		  	std::chrono::steady_clock::time_point «f.lastRunMember»{};
		  «ENDFOR»
		  «IF m.reactive && m.minIntervalNs > 0»
		  	bool reacted_ = false;
		  	std::chrono::steady_clock::time_point last_reaction_{};
		  «ENDIF»
		  «FOR p : m.outputs»
		  	rclcpp::Publisher<«p.rosType»>::SharedPtr «p.pubName»_;
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	rclcpp::Subscription<«p.rosType»>::SharedPtr «p.subName»_;
		  «ENDFOR»
		  «FOR l : linksOf(m)»
		  	rclcpp::Subscription<«l.trigger.rosType»>::SharedPtr link_«l.stem»_sub_;
		  	std::chrono::steady_clock::time_point link_«l.stem»_until_{};
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
			if (std::chrono::steady_clock::now() - «f.lastRunMember» >= std::chrono::nanoseconds(«f.minIntervalNs») ||
			    «f.lastRunMember» == std::chrono::steady_clock::time_point{}) {
			  «f.lastRunMember» = std::chrono::steady_clock::now();
			  «f.method»();
			}
		«ELSE»
			«f.method»();
		«ENDIF»
	'''

	def private main(PlannedModule m) '''
		// «banner»
		#include <memory>

		#include <rclcpp/rclcpp.hpp>

		#include "«m.layerId»/«m.className».hpp"

		int main(int argc, char** argv) {
		  rclcpp::init(argc, argv);
		  rclcpp::spin(std::make_shared<::«names.project»::«m.layerId»::«m.className»>(rclcpp::NodeOptions()));
		  rclcpp::shutdown();
		  return 0;
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
		`rsaml generate --target ros2`: a node per module (namespace: its layer), a timer per periodic
		function, a topic per group of connected ports, and `«pkg»/launch/«pkg».launch.py` to start them
		all. Put this directory in a colcon workspace's `src/`, then:

		```sh
		colcon build
		source install/setup.bash
		ros2 launch «pkg» «pkg».launch.py
		```

		`gen/`, `package.xml`, `CMakeLists.txt` and the launch file are regenerated every time; `src/`
		and the `.msg` files are yours, created once and never overwritten.
	'''
}
