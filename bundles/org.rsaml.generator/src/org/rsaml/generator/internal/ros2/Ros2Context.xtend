/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.TreeSet
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.LinkPlan
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.PlannedPort
import org.rsaml.analysis.plan.Release
import org.rsaml.analysis.plan.PlannedFunction
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.ReleaseBounds
import org.rsaml.generator.spi.OutputContext
import org.rsaml.model.TimeScaled

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
	/** The package named after the architecture (and C++ namespace): the launch files', and with packages single every node's. */
	public val String pkg
	/** Which package each node goes into (Architecture.packages). */
	public val Ros2Packages packages

	new(ExecutionPlan plan, String project, OutputContext output) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.rosNames = new Ros2Names(plan, names)
		this.output = output
		this.pkg = names.project
		this.packages = new Ros2Packages(plan, names)
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
		messagePackages(plan.modules)
	}

	/** ROS packages the nodes of these modules use, sorted. */
	def messagePackages(Iterable<PlannedModule> modules) {
		val used = new TreeSet<String>
		for (m : modules) {
			for (p : m.ports) {
				used += rosNames.rosPackage(p)
			}
		}
		used
	}

	/** The package of a module's node. */
	def nodePackage(PlannedModule m) {
		packages.of(m).name
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

	/** The parameter holding a release's period, in the unit of what is released. */
	def periodParameter(Release r) {
		val element = switch (r.kind) {
			case FUNCTION: r.function.function as TimeScaled
			case ACTION: r.action.action
			default: r.module.module
		}
		Ros2TimeParameter.of(names.method(r).replaceFirst("^release_", "") + ".period", r.periodNs, element)
	}

	/** The parameter holding a sporadic function's minimum interval, in the function's unit. */
	def intervalParameter(PlannedFunction f) {
		Ros2TimeParameter.of(names.method(f) + ".min_interval", f.minIntervalNs, f.function)
	}

	/** The parameter holding the least time between two reactions of a module, in the module's unit. */
	def reactionParameter(PlannedModule m) {
		Ros2TimeParameter.of("reaction.min_interval", rosNames.reactionIntervalNs(m), m.module)
	}

	/** The parameter holding how long a subsumption link stays active, in the link's unit. */
	def durationParameter(LinkPlan l) {
		Ros2TimeParameter.of(names.stem(l) + ".duration", l.durationNs, l.link)
	}

	/** The names of each node's time parameters, by node, as the launch files check the parameters file against them. */
	def timeNames() {
		val times = new java.util.LinkedHashMap<String, java.util.List<String>>
		for (m : plan.modules) {
			times.put(rosNames.rosNode(m), timeParameters(m).map[name].toList)
		}
		times
	}

	/**
	 * Every parameter the parameters file gives each node, by node name, with the model's value as
	 * the file writes it: the times in their units, then the QoS overrides. Generating again checks a
	 * kept file against them (Ros2ParamsCheck).
	 */
	def modelParameters() {
		val nodes = new java.util.LinkedHashMap<String, java.util.Map<String, String>>
		for (m : plan.modules) {
			val values = new java.util.LinkedHashMap<String, String>
			timeParameters(m).forEach[values.put(name, value)]
			values.putAll(qosParameters(m))
			nodes.put(rosNames.rosNode(m), values)
		}
		nodes
	}

	/**
	 * The QoS a module's node creates its publishers and subscriptions with, as the parameters that
	 * override it (qos_overrides.TOPIC.publisher|subscription.POLICY, TOPIC as the model names it).
	 */
	def qosParameters(PlannedModule m) {
		val parameters = new java.util.LinkedHashMap<String, String>
		for (p : m.outputs) {
			qos(p, "publisher", parameters)
		}
		for (p : m.inputs) {
			qos(p, "subscription", parameters)
		}
		for (l : linksOf(m)) {
			if (!m.inputs.exists[rosNames.topic(it) == rosNames.topic(l.trigger)]) {
				qos(l.trigger, "subscription", parameters)
			}
		}
		parameters
	}

	def private qos(PlannedPort p, String entity, java.util.Map<String, String> into) {
		rosNames.qosPolicies(p).forEach[policy, value|into.putIfAbsent("qos_overrides." + rosNames.topic(p) + "." + entity + "." + policy, value)]
	}

	/** Every time parameter of a module's node, in the order the node declares them. */
	def timeParameters(PlannedModule m) {
		val parameters = <Ros2TimeParameter>newArrayList
		m.releases.forEach[parameters += periodParameter(it)]
		m.stepFunctions.filter[minIntervalNs > 0].forEach[parameters += intervalParameter(it)]
		if (m.reactive && rosNames.reactionIntervalNs(m) > 0) {
			parameters += reactionParameter(m)
		}
		linksOf(m).forEach[parameters += durationParameter(it)]
		parameters
	}
}
