/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates

/** What every template of the ROS 2 target has at hand: the generation's context and text escapes. */
abstract class Ros2Template {

	protected val Ros2Context context
	protected val ExecutionPlan plan
	protected val String banner
	protected val String pkg

	new(Ros2Context context) {
		this.context = context
		this.plan = context.plan
		this.banner = context.banner
		this.pkg = context.pkg
	}

	/** A C++ string literal. */
	def protected str(String text) {
		Names.cppString(text)
	}

	/** A Python string literal. */
	def protected py(String text) {
		Names.pythonString(text)
	}

	def protected doc(String text) {
		Templates.doc(text)
	}

	def protected described(String text) {
		Templates.described(text)
	}
}
