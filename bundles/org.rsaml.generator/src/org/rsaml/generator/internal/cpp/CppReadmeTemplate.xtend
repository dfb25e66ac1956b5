/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.internal.cxx.CxxNames

/** The README.md of the generated project, the architect's once written. */
class CppReadmeTemplate extends CppTemplate {

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	def readme() '''
		# «doc(plan.name)»

		C++17 skeleton of the RsaML architecture '«doc(plan.name)»', created by `rsaml generate --target cpp`.

		```sh
		cmake -S . -B build
		cmake --build build -j
		./build/«names.project» --run-for-ms 1000
		```

		The program releases the periodic functions and actions at their modeled periods, passes data
		along the modeled connections and prints a trace of both (`--quiet` turns it off). It measures
		every job of a periodic release: a `miss` line when one completes after its deadline, an
		`overrun` line when one uses more CPU time than modeled, and at exit a `summary` line per release
		(jobs, worst response against the timing analysis's bound, worst execution time, its scheduling).
		`--busy-work 100` makes every job first consume its modeled execution time, to see the timing
		as analysed before the actions do real work; `--help` lists the options.

		- `gen/` is regenerated every time the model is generated again: do not edit it.
		- `src/` is yours: each module's class, where you implement its actions and input handlers, the
		  message types (`src/msg/`) and `src/user.cmake`. RsaML creates these files once and never
		  overwrites them.
	'''
}
