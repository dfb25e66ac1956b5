/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * What makes a node runnable: its registration as an rclcpp component (gen/LAYER/ModuleComponent.cpp)
 * and the executable that runs it in a process of its own (gen/LAYER/ModuleMain.cpp).
 */
class Ros2ComponentTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames

	new(Ros2Context context) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
	}

	def component(PlannedModule m) '''
		// «banner»
		// Registers node «doc(m.rosNode)» as the rclcpp component «context.plugin(m)».
		#include <rclcpp_components/register_node_macro.hpp>

		#include "«m.layerId»/«m.className».hpp"

		RCLCPP_COMPONENTS_REGISTER_NODE(«context.plugin(m)»)
	'''

	def nodeMain(PlannedModule m) '''
		// «banner»
		// Executable «m.executable»: node «doc(m.rosNode)» in a process of its own, each timed release on an
		// executor thread of its own at its real-time priority (rsaml/scheduling.hpp).
		#include "«m.layerId»/«m.className».hpp"

		int main(int argc, char** argv) {
		  return ::«names.project»::rsaml_ros2::run_standalone<«context.plugin(m)»>(argc, argv);
		}
	'''
}
