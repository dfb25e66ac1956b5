/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cxx

import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.PlannedPort
import org.rsaml.generator.internal.Templates

/**
 * The architect's class of a module (src/LAYER/Module.hpp and .cpp), created once, for every target
 * that emits C++: it derives from the generated base class and overrides its actions and entry-port
 * handlers. The targets differ only in what they call the module, what their base class does, how
 * ports are read and written, and the type and name of a handler's argument.
 */
class UserCode {

	val extension CxxNames names
	/** How the header's first line calls the module ("Module", "Node for module"). */
	val String kind
	/** What the generated base class does, completing "The generated base class (XBase, in gen/L/) ". */
	val String baseDoes
	/** The source's note on how ports are read and written (comment lines, without "// "). */
	val String ports
	/** The name of an entry-port handler's argument. */
	val String argument
	/** The C++ type of a port's value in that target. */
	val (PlannedPort)=>String type

	new(CxxNames names, String kind, String baseDoes, String ports, String argument, (PlannedPort)=>String type) {
		this.names = names
		this.kind = kind
		this.baseDoes = baseDoes
		this.ports = ports
		this.argument = argument
		this.type = type
	}

	def private doc(String text) {
		Templates.doc(text)
	}

	def private described(String text) {
		Templates.described(text)
	}

	def private ns(PlannedModule m) '''«names.project»::«m.layerId»'''

	/** The header: every action and handler declared with override. */
	def header(PlannedModule m) '''
		// «kind» «doc(m.qualifiedName)»«described(m.description)»
		// «Templates.USER_OWNED» The generated base class («m.baseName», in
		// gen/«m.layerId»/) «baseDoes» Each is marked override: when the model drops or renames one, the
		// compiler says so instead of silently no longer calling it.
		#pragma once

		#include "«m.layerId»/«m.baseName».hpp"

		namespace «ns(m)» {

		class «m.className» : public «m.baseName» {
		 public:
		  using «m.baseName»::«m.baseName»;

		 protected:
		  «FOR f : m.functions.filter[!actions.empty]»
		  	// Function «doc(f.name)»
		  	«FOR a : f.actions»
		  		void «a.method»() override;
		  	«ENDFOR»
		  «ENDFOR»
		  «IF !m.inputs.empty»
		  	// Entry ports
		  	«FOR p : m.inputs»
		  		void «p.onName»(«parameter(p)») override;
		  	«ENDFOR»
		  «ENDIF»
		};

		}  // namespace «ns(m)»
	'''

	/** The source: an empty body per action and handler. */
	def source(PlannedModule m) '''
		// «kind» «doc(m.qualifiedName)». «Templates.USER_OWNED»
		«FOR line : ports.split("\n")»
			// «line»
		«ENDFOR»
		#include "«m.layerId»/«m.className».hpp"

		namespace «ns(m)» {
		«FOR a : m.actions»

			// «doc(a.function.name)».«doc(a.name)»«described(a.description)»
			void «m.className»::«a.method»() {}
		«ENDFOR»
		«FOR p : m.inputs»

			// «doc(p.name)»«described(p.description)»
			void «m.className»::«p.onName»(«parameter(p)») { (void)«argument»; }
		«ENDFOR»

		}  // namespace «ns(m)»
	'''

	def private parameter(PlannedPort p) '''const «type.apply(p)»& «argument»'''
}
