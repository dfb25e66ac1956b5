/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.generator.internal.Templates

/**
 * config/&lt;pkg&gt;.params.yaml, the architect's (created once, never overwritten): every parameter
 * of every node with the model's value, times in the model's units and each topic's QoS, in the
 * format of ROS 2's parameter files. Both launch files load it; a node takes the model's value for
 * what the file does not set, which generating warns about each time (the file says to keep every line). The same text, regenerated, is gen/&lt;pkg&gt;.params.yaml: the
 * complete current file, from which the architect copies what the kept one lacks.
 */
class Ros2ParamsTemplate extends Ros2Template {

	val extension Ros2Names rosNames

	new(Ros2Context context) {
		super(context)
		this.rosNames = context.rosNames
	}

	/** The file's path in the output. */
	def path() {
		pkg + "/config/" + pkg + ".params.yaml"
	}

	/** The path of the regenerated copy: every parameter as the model now has it, never loaded. */
	def currentPath() {
		pkg + "/gen/" + pkg + ".params.yaml"
	}

	/** The architect's file, as created. */
	def params() {
		params(false)
	}

	/** The regenerated copy beside it. */
	def current() {
		params(true)
	}

	def private params(boolean current) '''
		«IF current»
			# «banner»
			# Every parameter of the nodes of the RsaML architecture '«doc(plan.name)»' as the model now has it: the
			# complete current form of «path.substring(pkg.length + 1)», which is yours and kept. No launch file loads this
			# copy: copy from it what yours lacks (generating warns, naming each node and parameter yours lacks).
		«ELSE»
			# Parameters of the nodes of the RsaML architecture '«doc(plan.name)»'. «Templates.USER_OWNED»
		«ENDIF»
		# Both launch files load «path.substring(pkg.length + 1)» (params_file:=PATH loads another file); a value there
		# overrides the model's. Keep every node and parameter in it: a node takes the model's value for one left out,
		# and generating again warns about each one left out, every time, until it is back
		# («currentPath.substring(pkg.length + 1)» has every one, regenerated each time). Generating again also warns,
		# naming the line, about a value that differs from the model's and a name no node has.
		# Times are in the model's units, as each name ends: _ns, _us, _ms or _s.
		# QoS of a topic: qos_overrides.TOPIC.publisher.POLICY or qos_overrides.TOPIC.subscription.POLICY
		# (reliability: reliable or best_effort; history: keep_last, or keep_all with «pkg»_processes.launch.py
		# only, as «pkg».launch.py shares messages within a container, which needs keep_last; depth: a
		# number, at least 1 with «pkg».launch.py), TOPIC
		# as the model names it: the launch files give the override to the topic's name as remapped
		# (a <topic>_topic:=NAME argument) and resolve a relative one in namespace:=NS, as ROS 2 names
		# the parameter after the resolved topic (/NS/NAME).
		«FOR m : plan.modules»
			«m.rosNode»:
			  ros__parameters:
			    # Module «doc(m.qualifiedName)»: «doc(m.timing)»
			    «FOR p : context.timeParameters(m)»
			    	«p.name»: «p.value»
			    «ENDFOR»
			    «FOR q : context.qosParameters(m).entrySet»
			    	«q.key»: «q.value»
			    «ENDFOR»
		«ENDFOR»
	'''
}
