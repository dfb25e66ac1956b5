/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.internal.cxx.CxxNames

/** The build: the generated CMakeLists.txt and the architect's src/user.cmake, which it includes. */
class CppCmakeTemplate extends CppTemplate {

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	def cmake() '''
		# «banner»
		# Your own settings (libraries, options, more sources) go in src/user.cmake.
		cmake_minimum_required(VERSION 3.16)
		project(«names.project» LANGUAGES CXX)

		set(CMAKE_CXX_STANDARD 17)
		set(CMAKE_CXX_STANDARD_REQUIRED ON)
		set(CMAKE_CXX_EXTENSIONS OFF)
		find_package(Threads REQUIRED)

		set(RSAML_TARGET «names.project»)
		add_executable(${RSAML_TARGET}
		  gen/main.cpp
		  gen/Architecture.cpp
		  «FOR f : CppTarget.RUNTIME_SOURCES»
		  	gen/rsaml/«f»
		  «ENDFOR»
		  «FOR m : plan.modules»
		  	«dir(m)»«m.baseName».cpp
		  	«userSourcePath(m)»
		  «ENDFOR»
		)
		target_include_directories(${RSAML_TARGET} PRIVATE gen src)
		target_link_libraries(${RSAML_TARGET} PRIVATE Threads::Threads)
		# Every source includes the runtime's header: compiled once, it halves the build time.
		target_precompile_headers(${RSAML_TARGET} PRIVATE gen/rsaml/runtime.hpp)
		include(src/user.cmake OPTIONAL)
	'''

	def userCmake() '''
		# Yours: created once by RsaML, never overwritten; the generated CMakeLists.txt includes it.
		# Add sources, libraries and options to the target ${RSAML_TARGET} here, for example:
		#   target_sources(${RSAML_TARGET} PRIVATE src/planner/Geometry.cpp)
		#   target_link_libraries(${RSAML_TARGET} PRIVATE Eigen3::Eigen)
	'''
}
