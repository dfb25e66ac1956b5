/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.Set
import java.util.TreeSet
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The package manifests (package.xml, REP 149 format 3) of the nodes' package and of the interfaces
 * package, with what the architect's package.user.xml adds.
 */
class Ros2PackageTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
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

	/**
	 * What colcon test needs: ament_lint_auto (the linters a package.user.xml names as test_depend
	 * run on src/) and launch_testing for the launch test.
	 */
	static val TEST_DEPENDS = #["ament_lint_auto", "launch_testing", "launch_testing_ament_cmake"]

	def packageXml(Ros2Manifest manifest) {
		val description = if (doc(plan.description).empty) "The RsaML architecture " + plan.name else plan.description
		val depends = new TreeSet<String>(#{"rclcpp", "rclcpp_components"})
		depends += context.messagePackages
		if (!context.rosNames.managedModules.empty) {
			depends += #["rclcpp_lifecycle", "lifecycle_msgs"]
		}
		val generated = <String>newHashSet
		generated += "buildtool_depend ament_cmake"
		depends.forEach[generated += "depend " + it]
		#["launch", "launch_ros", "ros2launch"].forEach[generated += "exec_depend " + it]
		TEST_DEPENDS.forEach[generated += "test_depend " + it]
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

			  «FOR d : TEST_DEPENDS»
			  	<test_depend>«d»</test_depend>
			  «ENDFOR»
			  «FOR d : manifest.dependencies(generated)»
			  	«d»
			  «ENDFOR»

			  <export>
			    <build_type>ament_cmake</build_type>
			  </export>
			</package>
		'''
	}

	/** The manifest of the package named after the architecture when the nodes are in packages of their own: the launch files and the parameters file. */
	def systemPackageXml(Ros2Manifest manifest) {
		val description = if (doc(plan.description).empty) "The RsaML architecture " + plan.name else plan.description
		val run = new TreeSet<String>
		run += context.packages.runtime
		context.packages.nodePackages.forEach[run += name]
		run += #["launch", "launch_ros", "ros2launch"]
		manifestXml(pkg, doc(description) + " (launch files and parameters)", manifest, #[], run, TEST_DEPENDS)
	}

	/** The manifest of the runtime package: the scheduling runtime, the component container, the lifecycle manager. */
	def runtimePackageXml(Ros2Manifest manifest) {
		val depends = new TreeSet<String>(#{"rclcpp", "rclcpp_components"})
		if (!context.rosNames.managedModules.empty) {
			depends += "lifecycle_msgs"
		}
		manifestXml(context.packages.runtime, "The scheduling runtime and component container of the RsaML architecture " + doc(plan.name),
			manifest, depends, #[], #[])
	}

	/** The manifest of a package of nodes: what its nodes use, and the runtime package. */
	def nodesPackageXml(Ros2Packages.NodePackage np, Ros2Manifest manifest) {
		val depends = new TreeSet<String>(#{"rclcpp", "rclcpp_components", context.packages.runtime})
		depends += context.messagePackages(np.modules)
		if (np.modules.exists[rosNames.managed(it)]) {
			depends += "rclcpp_lifecycle"
		}
		manifestXml(np.name, "The nodes of " + np.holds + " of the RsaML architecture " + doc(plan.name), manifest, depends, #[],
			TEST_DEPENDS + #["launch_ros", "rclpy"])
	}

	/** A package.xml of ament_cmake with these dependencies and what the architect's package.user.xml adds. */
	def private manifestXml(String name, String description, Ros2Manifest manifest, Iterable<String> depends, Iterable<String> execDepends,
			Iterable<String> testDepends) {
		val generated = <String>newHashSet
		generated += "buildtool_depend ament_cmake"
		depends.forEach[generated += "depend " + it]
		execDepends.forEach[generated += "exec_depend " + it]
		testDepends.forEach[generated += "test_depend " + it]
		'''
			<?xml version="1.0"?>
			<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
			<!-- «Names.xml(banner)» -->
			<!-- Version, maintainers, licences, URLs, authors and further dependencies: «Ros2Manifest.FILE» (yours). -->
			<package format="3">
			  <name>«name»</name>
			  <version>«manifest.version»</version>
			  <description>«Names.xml(description)»</description>
			  «people(manifest)»

			  <buildtool_depend>ament_cmake</buildtool_depend>
			  «IF !depends.empty»

			  	«FOR p : depends»
			  		<depend>«p»</depend>
			  	«ENDFOR»
			  «ENDIF»
			  «IF !execDepends.empty»

			  	«FOR p : execDepends»
			  		<exec_depend>«p»</exec_depend>
			  	«ENDFOR»
			  «ENDIF»
			  «IF !testDepends.empty»

			  	«FOR p : testDepends»
			  		<test_depend>«p»</test_depend>
			  	«ENDFOR»
			  «ENDIF»
			  «FOR d : manifest.dependencies(generated)»
			  	«d»
			  «ENDFOR»

			  <export>
			    <build_type>ament_cmake</build_type>
			  </export>
			</package>
		'''
	}

	def interfacesPackageXml(Ros2Manifest manifest, Set<String> deps) {
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
}
