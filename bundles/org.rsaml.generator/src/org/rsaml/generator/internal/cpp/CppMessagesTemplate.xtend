/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cpp.CppNames.MessageStruct
import org.rsaml.generator.internal.cxx.CxxNames

/** The structured data types: gen/messages.hpp and each type's struct of the architect's (src/msg/). */
class CppMessagesTemplate extends CppTemplate {

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	/** The architect's message structs. */
	def structs() {
		cppNames.messageStructs
	}

	def messages() '''
		// «banner»
		// The structured data types of the architecture; each is yours, in src/msg/.
		#pragma once

		«FOR t : cppNames.messageStructs»
			#include "«t.cppHeader»"
		«ENDFOR»
	'''

	def userMessage(MessageStruct t) '''
		// Message type «doc(t.key)» of architecture '«doc(plan.name)»'.
		// «Templates.USER_OWNED» Add the fields your modules exchange; the
		// type must stay default-constructible and copyable.
		#pragma once

		namespace «names.project»::msg«FOR n : t.cppNamespaces»::«n»«ENDFOR» {

		struct «t.cppStruct» {
		  // double x = 0.0;
		};

		}  // namespace «names.project»::msg«FOR n : t.cppNamespaces»::«n»«ENDFOR»
	'''
}
