/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.PlannedAction
import org.rsaml.analysis.plan.PlannedFunction
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.Reaction
import org.rsaml.analysis.plan.Release
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.OneMachineCpus
import org.rsaml.generator.internal.cxx.ReleaseBounds
import org.rsaml.model.SchedulingPolicy
import org.rsaml.model.support.RsamlLabels

/**
 * A module's generated base class, gen/LAYER/ModuleBase.hpp and .cpp: its typed ports, its timed
 * releases and reactions with what the runtime measures their jobs against, and how a release or
 * an arrival runs its functions and actions.
 */
class CppModuleTemplate extends CppTemplate {

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	def private posixPolicy(Release r) {
		if (r.edf) "Deadline"
		else if (r.policy == SchedulingPolicy.RR) "RoundRobin"
		else "Fifo"
	}

	/** The jobs' deadline, modeled cost and analysed bound, which the runtime measures each job against. */
	def private jobBounds(Release r) {
		jobBounds(r.deadlineNs, r.costNs, bounds.of(r))
	}

	def private jobBounds(long deadlineNs, long costNs, ReleaseBounds.Bound bound) '''::rsaml::JobBounds{«nanos(deadlineNs)», «nanos(costNs)», «nanos(bound.responseNs)»}'''

	def private reactionBounds(Reaction x) '''
		// reactions: from the arrival that starts one to its completion, due within «x.deadlineNs» ns (0: none),
		// modeled to take «x.costNs» ns; «boundComment(bounds.of(x))».
		::rsaml::Module::measure_reactions(«str(x.label)», «jobBounds(x.deadlineNs, x.costNs, bounds.of(x))»);
		«IF bounds.aperiodic(x)»
			// aperiodic reactions, which the analysis excludes: the module's data at the default priority, below every
			// real-time thread, so that more data than the module can react to takes no real-time time from the releases
			::rsaml::Module::serve_data_unbounded();
		«ENDIF»
	'''

	def private boundComment(Release r) {
		boundComment(bounds.of(r))
	}

	def private boundComment(ReleaseBounds.Bound bound) {
		if (bound.responseNs >= 0) '''analysed worst-case response «bound.responseNs» ns («doc(bound.why)»)'''
		else '''no analysed bound: «doc(bound.why)»'''
	}

	def baseHeader(PlannedModule m) '''
		// «banner»
		#pragma once

		#include <string>

		#include "messages.hpp"
		#include "rsaml/runtime.hpp"

		namespace «ns(m)» {

		/**
		 * Module «doc(m.qualifiedName)»«described(m.description)»
		 * Timing: «doc(m.timing)». «activation(m)»
		 * The generated part: «m.className» (src/«m.layerId»/«m.className».hpp, yours) derives from it.
		 */
		class «m.baseName» : public ::rsaml::Module {
		 public:
		  explicit «m.baseName»(::rsaml::System& system);
		  «IF !m.inputs.empty»

		  	// Entry ports: value() is the latest value received.
		  	«FOR p : m.inputs»
		  		::rsaml::Input<«p.cppType»> «p.inName»;  // «doc(p.name)»«described(p.description)»
		  	«ENDFOR»
		  «ENDIF»
		  «IF !m.outputs.empty»

		  	// Output ports: set value; it is sent after each activation (or call send() to send at once).
		  	«FOR p : m.outputs»
		  		::rsaml::Output<«p.cppType»> «p.outName»;  // «doc(p.name)»«described(p.description)»
		  	«ENDFOR»
		  «ENDIF»

		 protected:
		  «FOR f : m.functions»
		  	/** Function «doc(f.name)» («doc(f.timing)»)«described(f.description)» */
		  	virtual void «f.method»();
		  	«FOR a : f.actions»
		  		/** Action «doc(a.name)» («doc(a.timing)»)«described(a.description)» */
		  		virtual void «a.method»();
		  	«ENDFOR»
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	/** Called on each arrival at «doc(p.name)» that the module's mailbox takes, before the module reacts (a message that finds every slot of the mailbox taken, `rsaml::MAILBOX_SLOTS`, is dropped and said in the trace: docs/timing.md, "Memory between threads"). */
		  	virtual void «p.onName»(const «p.cppType»& value);
		  «ENDFOR»
		  void publish_outputs() override;

		 private:
		  «FOR r : m.releases»
		  	void «r.method»();
		  «ENDFOR»
		  «FOR p : m.inputs»
		  	void «p.receiveName»(const «p.cppType»& value);
		  «ENDFOR»
		  «IF m.reactive»
		  	void «m.reactMethod»();
		  «ENDIF»
		  «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		  	::rsaml::Clock::time_point «f.lastRunMember»{};
		  «ENDFOR»
		};

		}  // namespace «ns(m)»
	'''

	def private activation(PlannedModule m) {
		if (m.periodic) '''Periodic: released every period.'''
		else if (m.reactive) '''Reacts to arriving data«IF m.minIntervalNs > 0» (sporadic: at most once every «m.minIntervalNs» ns)«ENDIF».'''
		else '''Runs at the releases of its periodic functions and actions.'''
	}

	def baseSource(PlannedModule m) '''
		// «banner»
		#include "«m.layerId»/«m.baseName».hpp"

		namespace «ns(m)» {

		«m.baseName»::«m.baseName»(::rsaml::System& system)
		    : ::rsaml::Module(system, «str(m.qualifiedName)»«IF m.core >= 0 || !RsamlLabels.host(m.processor).empty», «m.core»«ENDIF»«IF !RsamlLabels.host(m.processor).empty», «str(RsamlLabels.host(m.processor))», «OneMachineCpus.cpu(m.processor)»«ENDIF»)«FOR p : m.inputs»,
		      «p.inName»(*this, «str(p.name)», [this](const «p.cppType»& value) { «p.receiveName»(value); })«ENDFOR»«FOR p : m.outputs»,
		      «p.outName»(*this, «str(p.name)»)«ENDFOR» {
		  «FOR r : m.releases»
		  	// «r.kind.name.toLowerCase» «doc(r.label)»: every «r.periodNs» ns from «r.offsetNs» ns; «r.why».
		  	// Due within «r.deadlineNs» ns, modeled to take «r.costNs» ns; «boundComment(r)».
		  	system.every(*this, «str(r.label)», «nanos(r.periodNs)», «nanos(r.offsetNs)», ::rsaml::Policy::«r.posixPolicy», «r.rank»,
		  	             «jobBounds(r)», [this] { «r.method»(); });
		  «ENDFOR»
		  «IF m.reactive»
		  	«reactionBounds(m.reaction)»
		  «ENDIF»
		}
		«FOR f : m.functions»

			void «m.baseName»::«f.method»() {
			  «FOR a : f.inlineActions»
			  	«runAction(a)»
			  «ENDFOR»
			}
			«FOR a : f.actions»

				void «m.baseName»::«a.method»() {}
			«ENDFOR»
		«ENDFOR»
		«FOR p : m.inputs»

			void «m.baseName»::«p.onName»(const «p.cppType»&) {}
		«ENDFOR»

		void «m.baseName»::publish_outputs() {
		  «FOR p : m.outputs»
		  	«p.outName».send();
		  «ENDFOR»
		}
		«FOR r : m.releases»

			void «m.baseName»::«r.method»() {
			  «release(r)»
			  publish_outputs();
			}
		«ENDFOR»
		«FOR p : m.inputs»

			void «m.baseName»::«p.receiveName»(const «p.cppType»& value) {
			  «p.onName»(value);
			  «IF m.reactive»
			  	«m.reactMethod»();
			  «ENDIF»
			}
		«ENDFOR»
		«IF m.reactive»

			void «m.baseName»::«m.reactMethod»() {
			  ::rsaml::Module::react(«nanos(m.minIntervalNs)», [this] {
			    «FOR f : m.stepFunctions»
			    	«callFunction(f)»
			    «ENDFOR»
			    publish_outputs();
			  });
			}
		«ENDIF»

		}  // namespace «ns(m)»
	'''

	def private runAction(PlannedAction a) '''
		::rsaml::Module::run_action(«str(a.function.name + "." + a.name)», «nanos(a.offsetNs)», [this] { «a.method»(); });
	'''

	def private callFunction(PlannedFunction f) '''
		«IF f.minIntervalNs > 0»
			if (::rsaml::Module::due(«f.lastRunMember», «nanos(f.minIntervalNs)»)) {
			  «f.method»();
			}
		«ELSE»
			«f.method»();
		«ENDIF»
	'''

	def private release(Release r) {
		switch (r.kind) {
			case FUNCTION: '''«r.function.method»();'''
			case ACTION: runAction(r.action)
			default: '''
				«FOR f : r.module.stepFunctions»
					«callFunction(f)»
				«ENDFOR»
			'''
		}
	}
}
