/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.Set
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The CMakeLists.txt of the nodes' package and of the interfaces package, and the user.cmake each
 * starts with (the architect's, created once).
 */
class Ros2CmakeTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames

	val Ros2LaunchTestTemplate launchTest

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
		this.launchTest = new Ros2LaunchTestTemplate(context)
	}

	def interfacesCmake(Set<String> deps) '''
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
		  «FOR t : context.generatedMessages»
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

	def cmake() '''
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
		«IF managed»
			find_package(rclcpp_lifecycle REQUIRED)
			find_package(lifecycle_msgs REQUIRED)
		«ENDIF»
		find_package(Threads REQUIRED)
		«FOR p : context.messagePackages»
			find_package(«p» REQUIRED)
		«ENDFOR»

		add_library(${PROJECT_NAME} SHARED
		  «FOR f : Ros2Target.RUNTIME_SOURCES»
		  	gen/rsaml/«f»
		  «ENDFOR»
		  «FOR m : plan.modules»
		  	gen/«m.layerId»/«m.className»Component.cpp
		  	src/«m.layerId»/«m.className».cpp
		  «ENDFOR»
		)
		target_include_directories(${PROJECT_NAME} PUBLIC gen src)
		target_link_libraries(${PROJECT_NAME} PUBLIC rclcpp::rclcpp«IF managed» rclcpp_lifecycle::rclcpp_lifecycle«ENDIF» Threads::Threads«FOR p : context.messagePackages» ${«p»_TARGETS}«ENDFOR» PRIVATE rclcpp_components::component)
		rclcpp_components_register_nodes(${PROJECT_NAME}
		  «FOR m : plan.modules»
		  	"«context.plugin(m)»"
		  «ENDFOR»
		)

		«runtimeExecutables»
		# An executable per node, scheduled as in the container.
		«FOR m : plan.modules»
			add_executable(«m.executable» gen/«m.layerId»/«m.mainName».cpp)
			target_link_libraries(«m.executable» PRIVATE ${PROJECT_NAME})
		«ENDFOR»

		include(user.cmake)

		«testing(launchTest.path)»

		install(TARGETS ${PROJECT_NAME} ARCHIVE DESTINATION lib LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
		install(TARGETS «rosNames.containerExecutable»«IF managed» «rosNames.lifecycleManagerExecutable»«ENDIF»«FOR m : plan.modules» «m.executable»«ENDFOR» DESTINATION lib/${PROJECT_NAME})
		install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})

		ament_package()
	'''

	/**
	 * The BUILD_TESTING block of a package: the linters its package.user.xml names, where installed,
	 * and its launch test at {@code launchTestPath} (that of the package that holds the launch files, or
	 * of a package of nodes), null for none.
	 */
	def private testing(String launchTestPath) '''
		if(BUILD_TESTING)
		  # The linters package.user.xml names as <test_depend> (ament_lint_common, ament_cmake_cpplint,
		  # ...), where installed; what is regenerated (gen/, the launch files and the launch test) is
		  # not theirs to judge (ROS 2 Iron and later).
		  find_package(ament_lint_auto QUIET)
		  if(ament_lint_auto_FOUND)
		    file(GLOB_RECURSE AMENT_LINT_AUTO_FILE_EXCLUDE gen/*«IF launchTestPath == launchTest.path» launch/*.launch.py«ENDIF»«IF launchTestPath !== null» «launchTestPath»«ENDIF»)
		    ament_lint_auto_find_test_dependencies()
		  endif()
		  «IF launchTestPath !== null»
		  	# The launch test: starts the nodes, checks that messages flow and that they exit cleanly.
		  	find_package(launch_testing_ament_cmake QUIET)
		  	if(launch_testing_ament_cmake_FOUND)
		  	  add_launch_test(«launchTestPath» TIMEOUT 120)
		  	else()
		  	  message(STATUS "launch_testing_ament_cmake not found: «launchTestPath» is not run")
		  	endif()
		  «ENDIF»
		endif()
	'''

	/**
	 * The executables of the package that holds the scheduling runtime: the component container of the launch
	 * files, and the lifecycle manager when some node is managed.
	 */
	def private runtimeExecutables() '''
		# The component container of the launch file: each timed release on a thread at its priority.
		add_executable(«rosNames.containerExecutable» gen/rsaml/«Ros2Target.CONTAINER_SOURCE»)
		target_link_libraries(«rosNames.containerExecutable» PRIVATE ${PROJECT_NAME} rclcpp_components::component_manager)

		«IF managed»
			# The lifecycle manager of the launch files: configures and activates the managed nodes, and deactivates and cleans them up on SIGINT.
			add_executable(«rosNames.lifecycleManagerExecutable» gen/rsaml/«Ros2Target.LIFECYCLE_MANAGER_SOURCE»)
			target_link_libraries(«rosNames.lifecycleManagerExecutable» PRIVATE rclcpp::rclcpp ${lifecycle_msgs_TARGETS})
			target_include_directories(«rosNames.lifecycleManagerExecutable» PRIVATE gen)

		«ENDIF»
	'''

	/** Whether some node is managed: then the package uses rclcpp_lifecycle and builds the lifecycle manager. */
	def private managed() {
		!rosNames.managedModules.empty
	}

	/**
	 * The CMakeLists.txt of a package of nodes (packages perLayer or perProcessor): its nodes as
	 * components of the shared library ${PROJECT_NAME} and an executable each, on the scheduling
	 * runtime of the runtime package.
	 */
	def nodesCmake(Ros2Packages.NodePackage np) {
		val runtime = context.packages.runtime
		val lifecycle = np.modules.exists[rosNames.managed(it)]
		val messages = context.messagePackages(np.modules)
		'''
			# «banner»
			# The nodes of «Names.comment(np.holds)»: each an rclcpp component of the shared library
			# ${PROJECT_NAME} and an executable of its own, on the scheduling runtime of «runtime».
			# Your additions go in user.cmake, included below.
			cmake_minimum_required(VERSION 3.8)
			project(«np.name» LANGUAGES CXX)

			if(NOT CMAKE_CXX_STANDARD)
			  set(CMAKE_CXX_STANDARD 17)
			  set(CMAKE_CXX_STANDARD_REQUIRED ON)
			endif()

			find_package(ament_cmake REQUIRED)
			find_package(rclcpp REQUIRED)
			find_package(rclcpp_components REQUIRED)
			«IF lifecycle»
				find_package(rclcpp_lifecycle REQUIRED)
			«ENDIF»
			find_package(Threads REQUIRED)
			find_package(«runtime» REQUIRED)
			«FOR p : messages»
				find_package(«p» REQUIRED)
			«ENDFOR»

			add_library(${PROJECT_NAME} SHARED
			  «FOR m : np.modules»
			  	gen/«m.layerId»/«m.className»Component.cpp
			  	src/«m.layerId»/«m.className».cpp
			  «ENDFOR»
			)
			target_include_directories(${PROJECT_NAME} PUBLIC gen src)
			target_link_libraries(${PROJECT_NAME} PUBLIC «runtime»::«runtime» rclcpp::rclcpp«IF lifecycle» rclcpp_lifecycle::rclcpp_lifecycle«ENDIF» Threads::Threads«FOR p : messages» ${«p»_TARGETS}«ENDFOR» PRIVATE rclcpp_components::component)
			rclcpp_components_register_nodes(${PROJECT_NAME}
			  «FOR m : np.modules»
			  	"«context.plugin(m)»"
			  «ENDFOR»
			)

			# An executable per node, scheduled as in the container of «runtime».
			«FOR m : np.modules»
				add_executable(«m.executable» gen/«m.layerId»/«m.mainName».cpp)
				target_link_libraries(«m.executable» PRIVATE ${PROJECT_NAME})
			«ENDFOR»

			include(user.cmake)

			«testing(launchTest.path(np))»

			install(TARGETS ${PROJECT_NAME} ARCHIVE DESTINATION lib LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
			install(TARGETS«FOR m : np.modules» «m.executable»«ENDFOR» DESTINATION lib/${PROJECT_NAME})

			ament_package()
		'''
	}

	/**
	 * The CMakeLists.txt of the runtime package (packages perLayer or perProcessor): the scheduling
	 * runtime as the shared library ${PROJECT_NAME}, exported with its headers to the packages of
	 * nodes, which must share it in a process (the container finds their releases through it); the
	 * component container; the lifecycle manager when some node is managed.
	 */
	def runtimeCmake() '''
		# «banner»
		# The scheduling runtime of the nodes' packages (the shared library ${PROJECT_NAME}, which they
		# link: the nodes of a container share it), the component container of the launch files«IF managed»
		# and the lifecycle manager«ENDIF». Your additions go in user.cmake, included below.
		cmake_minimum_required(VERSION 3.8)
		project(«context.packages.runtime» LANGUAGES CXX)

		if(NOT CMAKE_CXX_STANDARD)
		  set(CMAKE_CXX_STANDARD 17)
		  set(CMAKE_CXX_STANDARD_REQUIRED ON)
		endif()

		find_package(ament_cmake REQUIRED)
		find_package(rclcpp REQUIRED)
		find_package(rclcpp_components REQUIRED)
		«IF managed»
			find_package(lifecycle_msgs REQUIRED)
		«ENDIF»
		find_package(Threads REQUIRED)

		add_library(${PROJECT_NAME} SHARED«FOR f : Ros2Target.RUNTIME_SOURCES» gen/rsaml/«f»«ENDFOR»)
		target_include_directories(${PROJECT_NAME} PUBLIC
		  "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/gen>" "$<INSTALL_INTERFACE:include/${PROJECT_NAME}>")
		target_link_libraries(${PROJECT_NAME} PUBLIC rclcpp::rclcpp Threads::Threads)

		«runtimeExecutables»
		include(user.cmake)

		install(DIRECTORY gen/rsaml DESTINATION include/${PROJECT_NAME} FILES_MATCHING PATTERN "*.hpp")
		install(TARGETS ${PROJECT_NAME} EXPORT export_${PROJECT_NAME} ARCHIVE DESTINATION lib LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
		install(TARGETS «rosNames.containerExecutable»«IF managed» «rosNames.lifecycleManagerExecutable»«ENDIF» DESTINATION lib/${PROJECT_NAME})

		ament_export_targets(export_${PROJECT_NAME} HAS_LIBRARY_TARGET)
		ament_export_dependencies(rclcpp)
		ament_package()
	'''

	/**
	 * The CMakeLists.txt of the package named after the architecture when the nodes are in packages
	 * of their own: the launch files and the parameters file.
	 */
	def systemCmake() '''
		# «banner»
		# The launch files and the parameters file of the architecture; the nodes are in the packages
		# «FOR np : context.packages.nodePackages SEPARATOR ", "»«np.name»«ENDFOR», the container«IF managed» and the lifecycle manager«ENDIF» in
		# «context.packages.runtime». Your additions go in user.cmake, included below.
		cmake_minimum_required(VERSION 3.8)
		project(«pkg» NONE)

		find_package(ament_cmake REQUIRED)

		include(user.cmake)

		«testing(launchTest.path)»

		install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})

		ament_package()
	'''

	def runtimeUserCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# ament_package(). The scheduling runtime is the shared library ${PROJECT_NAME}.
	'''

	def systemUserCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# ament_package(). This package holds the launch files and the parameters file; install more of
		# yours here, e.g.
		#   install(DIRECTORY maps DESTINATION share/${PROJECT_NAME})
		# The nodes are built in their own packages: what they need goes in their user.cmake.
	'''

	def interfacesUserCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# rosidl_generate_interfaces(). Your own interface files, for example:
		#   list(APPEND RSAML_USER_INTERFACES "srv/SetSpeed.srv" "action/Move.action")
		# Packages their fields use go in «Ros2Manifest.FILE» (<depend>geometry_msgs</depend>).
	'''

	def userCmake() '''
		# «Templates.USER_OWNED» CMakeLists.txt includes it before
		# ament_package(). The nodes are the shared library ${PROJECT_NAME}; add what they need, e.g.
		#   find_package(tf2_ros REQUIRED)
		#   target_link_libraries(${PROJECT_NAME} PRIVATE tf2_ros::tf2_ros)
		# and name the package in «Ros2Manifest.FILE» (<depend>tf2_ros</depend>).
	'''
}
