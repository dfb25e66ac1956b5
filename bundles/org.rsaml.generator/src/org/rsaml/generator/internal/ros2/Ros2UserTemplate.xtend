/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.UserCode
import org.rsaml.generator.internal.ros2.Ros2Names.RosMessage

/**
 * The architect's files, created once: each node's own class (the C++ user code every C++ target
 * shares, in ROS 2's words) and the .msg files of the message types the interfaces package defines.
 */
class Ros2UserTemplate extends Ros2Template {

	val extension Ros2Names rosNames
	val UserCode code

	new(Ros2Context context) {
		super(context)
		this.rosNames = context.rosNames
		this.code = new UserCode(context.names, "Node for module",
			"creates the publishers, subscriptions and timers; implement the actions and\n// message handlers here.",
			"Inputs: in_<port> is the latest message, shared and not copied (a ConstSharedPtr: keep it to keep\nthe message; null until the first arrives); on_<port> gets each one as a const reference.\nOutputs: set out_<port>; a copy of it is published after each activation of the node. Or hand a\nmessage over without a copy: send_<port>(std::make_unique<T>(...)) publishes it at once.",
			"message", [rosType])
	}

	/** src/LAYER/Module.hpp */
	def header(PlannedModule m) {
		code.header(m)
	}

	/** src/LAYER/Module.cpp */
	def source(PlannedModule m) {
		code.source(m)
	}

	/** msg/Type.msg of the interfaces package: comments only, the architect declares the fields. */
	def message(RosMessage t) '''
		# Message type «Names.comment(t.key)» of architecture '«Names.comment(plan.name)»'.
		# «Templates.USER_OWNED» Declare its fields, for example:
		# float64 x
		# std_msgs/Header header
		# Types of other packages are found when you generate again, and declared as dependencies.
	'''
}
