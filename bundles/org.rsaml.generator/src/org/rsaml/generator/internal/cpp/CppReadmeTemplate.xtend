/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * The project's README.md, the architect's (created once, never overwritten), and GENERATED.md beside
 * it, regenerated every time with what the generation made of the model (the program, the modules and
 * their files, the files that are yours), so that a README written long ago never states stale facts:
 * it links GENERATED.md.
 */
class CppReadmeTemplate extends CppTemplate {

	/** The regenerated file the README links. */
	static val GENERATED = Templates.GENERATED_README

	val extension CxxNames cxx
	val extension CppNames cpp

	new(ExecutionPlan plan, CxxNames names) {
		super(plan, names)
		this.cxx = names
		this.cpp = cppNames
	}

	/** The README the architect starts with: what the project is, how to run it, and the link to GENERATED.md. */
	def readme() '''
		# «doc(plan.name)»

		C++17 skeleton of the RsaML architecture '«doc(plan.name)»', created by `rsaml generate --target cpp`.
		This README is yours: created once, never overwritten; say here what your program is for.

		**[«GENERATED»](«GENERATED»)** is regenerated from the model every time: how to build and run
		the program, its modules and their files, and which files are yours.

		```sh
		cmake -S . -B build
		cmake --build build -j
		./build/«names.project» --run-for-ms 1000
		```
	'''

	/** GENERATED.md: the facts of this generation, regenerated every time. */
	def generated() '''
		<!-- «banner.replace("--", "- -")» Your notes go in README.md. -->
		# «doc(plan.name)»: what RsaML generated

		C++17 skeleton of the RsaML architecture '«doc(plan.name)»', created by `rsaml generate --target cpp`:
		a class per module and one program, `«names.project»`. This file is regenerated every time (edit
		the model, or README.md for notes of yours).

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

		Modules (the generated part in `gen/`, your class in `src/`):
		«FOR m : plan.modules»
			- `«doc(m.qualifiedName)»`: `«m.layerId»::«m.className»` (`src/«m.layerId»/«m.className».hpp`, `.cpp`)
		«ENDFOR»
		«IF !structs.empty»

		Message types (yours, in `src/`): «FOR t : structs SEPARATOR ", "»`«t.cppHeader»`«ENDFOR».
		«ENDIF»

		- `gen/`, `CMakeLists.txt` and this file are regenerated every time the model is generated again:
		  do not edit them.
		- `src/` is yours: each module's class, where you implement its actions and input handlers, the
		  message types (`src/msg/`) and `src/user.cmake`; and `README.md`. RsaML creates these files
		  once and never overwrites them.
	'''

	def private structs() {
		new CppMessagesTemplate(plan, names).structs
	}
}
