/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.ReleaseBounds

/**
 * What every template of the C++ target has at hand: the plan, its names, the timing analysis's
 * bounds, the first line of every regenerated file, where a module's files go, and text escapes.
 */
abstract class CppTemplate {

	protected val ExecutionPlan plan
	protected val CxxNames names
	protected val CppNames cppNames
	/** The first line of every regenerated file. */
	protected val String banner
	/** The timing analysis's bound of each release and reaction, which the runtime measures jobs against. */
	protected val ReleaseBounds bounds

	new(ExecutionPlan plan, CxxNames names) {
		this.plan = plan
		this.names = names
		this.cppNames = new CppNames(plan, names)
		this.banner = Templates.banner(plan)
		this.bounds = ReleaseBounds.of(plan)
	}

	/** gen/LAYER/: a module's generated files. */
	def dir(PlannedModule m) '''gen/«names.layerId(m)»/'''

	/** gen/LAYER/ModuleBase.hpp */
	def baseHeaderPath(PlannedModule m) '''gen/«names.layerId(m)»/«names.baseName(m)».hpp'''

	/** src/LAYER/Module.cpp, the architect's. */
	def userSourcePath(PlannedModule m) '''src/«names.layerId(m)»/«names.className(m)».cpp'''

	def protected ns(PlannedModule m) '''«names.project»::«names.layerId(m)»'''

	def protected nanos(long value) '''::rsaml::Nanos(«value»)'''

	/** A C++ string literal. */
	def protected str(String text) {
		Names.cppString(text)
	}

	def protected doc(String text) {
		Templates.doc(text)
	}

	def protected described(String text) {
		Templates.described(text)
	}
}
