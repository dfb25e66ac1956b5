/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.LinkPlan
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.Release
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.ReleaseBounds
import org.rsaml.generator.spi.OutputContext

/**
 * What the templates of one ROS 2 generation share: the plan, its C++ and ROS names, the output
 * (the architect's files), and the facts several output files state (a node's plugin name, the
 * packages of its messages, the parameter names).
 */
class Ros2Context {

	public val ExecutionPlan plan
	public val CxxNames names
	public val Ros2Names rosNames
	public val OutputContext output
	/** The timing analysis's bound of each release, which the nodes measure their jobs against. */
	public val ReleaseBounds bounds
	/** The first line of every regenerated file. */
	public val String banner
	/** The nodes' package (and C++ namespace). */
	public val String pkg

	new(ExecutionPlan plan, String project, OutputContext output) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.rosNames = new Ros2Names(plan, names)
		this.output = output
		this.pkg = names.project
		this.banner = Templates.banner(plan)
		this.bounds = ReleaseBounds.of(plan)
	}

	/** What the analysis says of a release's response time, for a comment. */
	def boundComment(Release r) {
		val bound = bounds.of(r)
		if (bound.responseNs >= 0) "analysed worst-case response " + bound.responseNs + " ns (" + Names.comment(bound.why) + ")"
		else "no analysed bound: " + Names.comment(bound.why)
	}

	/** The rclcpp component a module's node is registered as. */
	def plugin(PlannedModule m) {
		names.project + "::" + names.layerId(m) + "::" + names.className(m)
	}

	/** The message types the interfaces package defines. */
	def generatedMessages() {
		rosNames.messages.filter[rosGenerated].toList
	}

	/** ROS packages the nodes use, sorted: std_msgs, the interfaces package, packages named on ports. */
	def messagePackages() {
		val packages = new TreeSet<String>
		for (m : plan.modules) {
			for (p : m.ports) {
				packages += rosNames.rosPackage(p)
			}
		}
		packages
	}

	/** The architect's package.user.xml of a package, or the defaults it starts with. */
	def manifest(String name) {
		val path = name + "/" + Ros2Manifest.FILE
		val text = output.userFile(path)
		if (text.present) Ros2Manifest.parse(path, text.get) else Ros2Manifest.initial(name)
	}

	/** Links whose state lives in this module's node: suppressors of its inputs, inhibitors of its outputs. */
	def linksOf(PlannedModule m) {
		val links = <LinkPlan>newArrayList
		m.inputs.forEach[links += suppressors]
		m.outputs.forEach[links += inhibitors]
		links
	}

	/** The parameter holding a release's period. */
	def periodParameter(Release r) {
		names.method(r).replaceFirst("^release_", "") + ".period_ns"
	}
}
