/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.LinkPlan
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The architecture as a program: gen/Architecture.hpp and .cpp (the modules, their connections and
 * subsumption links, as modeled) and gen/main.cpp.
 */
class CppArchitectureTemplate extends CppTemplate {

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	def architectureHeader() '''
		// «banner»
		#pragma once

		#include "rsaml/runtime.hpp"

		«FOR m : plan.modules»
			#include "«m.layerId»/«m.className».hpp"
		«ENDFOR»

		namespace «names.project» {

		/**
		 * Architecture «doc(plan.name)»: its modules, their connections and subsumption links, as modeled.
		«IF !doc(plan.description).empty»
			 * «doc(plan.description)»
		«ENDIF»
		 */
		class Architecture {
		 public:
		  Architecture();
		  int run(const ::rsaml::Options& options);

		 private:
		  ::rsaml::System system_;
		  «FOR m : plan.modules»
		  	«qualified(m)» «m.member»_;
		  «ENDFOR»
		  «FOR l : plan.links»
		  	::rsaml::Link «l.member»_;
		  «ENDFOR»
		};

		}  // namespace «names.project»
	'''

	def architectureSource() '''
		// «banner»
		#include "Architecture.hpp"

		namespace «names.project» {

		Architecture::Architecture()
		    : system_(«str(plan.name)»)«FOR m : plan.modules»,
		      «m.member»_(system_)«ENDFOR»«FOR l : plan.links»,
		      «l.member»_(«str(l.qualifiedName)», «nanos(l.durationNs)»)«ENDFOR» {
		  // Start steps run in this order: lowest layer first.
		  «FOR m : plan.modules»
		  	system_.add(«m.member»_);
		  «ENDFOR»
		  «IF !plan.flows.empty»

		  	// Connections.
		  	«FOR c : plan.flows»
		  		«c.source.module.member»_.«c.source.outName».connect(«c.target.module.member»_.«c.target.inName»);
		  	«ENDFOR»
		  «ENDIF»
		  «FOR l : plan.links BEFORE '\n'»
		  	«link(l)»
		  «ENDFOR»
		}

		int Architecture::run(const ::rsaml::Options& options) { return system_.run(options); }

		}  // namespace «names.project»
	'''

	def private link(LinkPlan l) '''
		«IF l.inhibitor»
			// Inhibitor «doc(l.qualifiedName)»: while active, blocks «doc(l.target.qualifiedName)».
			«l.trigger.module.member»_.«l.trigger.outName».triggers(«l.member»_);
			«l.target.module.member»_.«l.target.outName».inhibited_by(«l.member»_);
		«ELSE»
			// Suppressor «doc(l.qualifiedName)»: while active, replaces what «doc(l.target.qualifiedName)» receives.
			«l.trigger.module.member»_.«l.trigger.outName».triggers(«l.member»_«IF l.deliversData», «l.target.module.member»_.«l.target.inName»«ENDIF»);
			«l.target.module.member»_.«l.target.inName».suppressed_by(«l.member»_);
		«ENDIF»
	'''

	def main() '''
		// «banner»
		#include "Architecture.hpp"

		int main(int argc, char** argv) {
		  const ::rsaml::Options options = ::rsaml::parse_options(argc, argv, «str(names.project)»);
		  if (options.exit) {
		    return options.status;
		  }
		  ::«names.project»::Architecture architecture;
		  return architecture.run(options);
		}
	'''

	def private qualified(PlannedModule m) '''::«ns(m)»::«m.className»'''
}
