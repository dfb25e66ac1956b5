/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import java.io.IOException
import java.io.UncheckedIOException
import java.nio.charset.StandardCharsets
import org.rsaml.generator.internal.Names
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cpp.CppNames.MessageStruct
import org.rsaml.generator.internal.cxx.CxxCode
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.ReleaseBounds
import org.rsaml.generator.internal.cxx.UserCode
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.LinkPlan
import org.rsaml.analysis.plan.PlannedAction
import org.rsaml.analysis.plan.PlannedFunction
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.Reaction
import org.rsaml.analysis.plan.Release
import org.rsaml.generator.spi.GeneratedFile
import org.rsaml.generator.spi.GeneratedProject
import org.rsaml.generator.spi.OutputContext
import org.rsaml.generator.spi.TargetGenerator
import org.rsaml.model.SchedulingPolicy

/**
 * The C++17 target: a CMake project with one class per module. The generated part of each module
 * (gen/LAYER/ModuleBase.*) declares its typed ports, runs its functions and is regenerated; the
 * architect's part (src/LAYER/Module.*) implements the actions and is created once. The runtime
 * (gen/rsaml/) is the same for every model: the files runtime/cpp/rsaml/* of this bundle, and runtime/cxx/rsaml/realtime.hpp, which the ROS 2 nodes share.
 */
class CppTarget implements TargetGenerator {

	override id() {
		"cpp"
	}

	override description() {
		"a CMake C++17 project that builds and runs on its own (threads, timers, a trace of the run)"
	}

	override generate(ExecutionPlan plan, OutputContext output) {
		val warnings = <String>newArrayList
		val project = CxxNames.stableProject(plan, output.kept, warnings, "the C++ namespace, the CMake project and the program")
		new GeneratedProject(new CppFiles(plan, project).files, warnings, #{CxxNames.KEPT_PROJECT -> project})
	}

	/** The fixed runtime file at runtime/cpp/PATH in this bundle. */
	def static String runtimeFile(String path) {
		runtimeFile("cpp", path)
	}

	/**
	 * A fixed runtime file at runtime/DIR/PATH in this bundle: cpp (the C++ runtime), cxx (shared by
	 * the C++ runtime and the ROS 2 nodes).
	 */
	def static String runtimeFile(String dir, String path) {
		val in = CppTarget.getResourceAsStream("/runtime/" + dir + "/" + path)
		if (in === null) {
			throw new IllegalStateException("the C++ runtime file " + path + " is missing from org.rsaml.generator")
		}
		try {
			return new String(in.readAllBytes, StandardCharsets.UTF_8)
		} catch (IOException e) {
			throw new UncheckedIOException(e)
		} finally {
			in.close
		}
	}
}

/** The files of one plan. */
class CppFiles {

	val ExecutionPlan plan
	val extension CxxNames names
	val extension CppNames cppNames
	val String banner
	val ReleaseBounds bounds
	val UserCode userCode

	new(ExecutionPlan plan, String project) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.cppNames = new CppNames(plan, names)
		this.banner = Templates.banner(plan)
		this.bounds = ReleaseBounds.of(plan)
		this.userCode = new UserCode(names, "Module",
			"declares the ports and runs the functions; implement the actions and\n// input handlers here.",
			"Inputs: in_<port>.value() is the latest value. Outputs: set out_<port>.value; it is sent after\neach activation of the module (or call out_<port>.send() to send at once).",
			"value", [cppType])
	}

	def files() {
		val files = <GeneratedFile>newArrayList
		files += GeneratedFile.generated("CMakeLists.txt", cmake)
		files += GeneratedFile.generated("gen/rsaml/runtime.hpp", "// " + banner + "\n" + CppTarget.runtimeFile("rsaml/runtime.hpp"))
		files += GeneratedFile.generated("gen/rsaml/runtime.cpp", "// " + banner + "\n" + CppTarget.runtimeFile("rsaml/runtime.cpp"))
		files += GeneratedFile.generated("gen/rsaml/realtime.hpp", "// " + banner + "\n" + CppTarget.runtimeFile("cxx", "rsaml/realtime.hpp"))
		files += GeneratedFile.generated("gen/messages.hpp", messages)
		files += GeneratedFile.generated("gen/Architecture.hpp", architectureHeader)
		files += GeneratedFile.generated("gen/Architecture.cpp", architectureSource)
		files += GeneratedFile.generated("gen/main.cpp", main)
		for (m : plan.modules) {
			files += GeneratedFile.generated(baseHeaderPath(m).toString, baseHeader(m))
			files += GeneratedFile.generated(dir(m) + m.baseName + ".cpp", baseSource(m))
			files += GeneratedFile.user("src/" + m.layerId + "/" + m.className + ".hpp", userCode.header(m), m.hooks, m.stubs, CxxCode.IDENTIFIERS)
			files += GeneratedFile.user(userSourcePath(m).toString, userCode.source(m))
		}
		for (t : cppNames.messageStructs) {
			files += GeneratedFile.user("src/" + t.cppHeader, userMessage(t))
		}
		files += GeneratedFile.user("src/user.cmake", userCmake)
		files += GeneratedFile.user("README.md", readme)
		files
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
	'''

	def private boundComment(Release r) {
		boundComment(bounds.of(r))
	}

	def private boundComment(ReleaseBounds.Bound bound) {
		if (bound.responseNs >= 0) '''analysed worst-case response «bound.responseNs» ns («doc(bound.why)»)'''
		else '''no analysed bound: «doc(bound.why)»'''
	}

	def private dir(PlannedModule m) '''gen/«m.layerId»/'''

	def private baseHeaderPath(PlannedModule m) '''gen/«m.layerId»/«m.baseName».hpp'''

	def private userSourcePath(PlannedModule m) '''src/«m.layerId»/«m.className».cpp'''

	def private ns(PlannedModule m) '''«names.project»::«m.layerId»'''

	def private qualified(PlannedModule m) '''::«ns(m)»::«m.className»'''

	def private nanos(long value) '''::rsaml::Nanos(«value»)'''

	def private str(String text) {
		Names.cppString(text)
	}

	def private doc(String text) {
		Templates.doc(text)
	}

	def private described(String text) {
		Templates.described(text)
	}

	def private cmake() '''
		# «banner»
		# Your own settings (libraries, options, more sources) go in src/user.cmake.
		cmake_minimum_required(VERSION 3.16)
		project(«names.project» LANGUAGES CXX)

		set(CMAKE_CXX_STANDARD 17)
		set(CMAKE_CXX_STANDARD_REQUIRED ON)
		set(CMAKE_CXX_EXTENSIONS OFF)
		find_package(Threads REQUIRED)

		set(RSAML_TARGET «names.project»)
		add_executable(${RSAML_TARGET}
		  gen/main.cpp
		  gen/Architecture.cpp
		  gen/rsaml/runtime.cpp
		  «FOR m : plan.modules»
		  	«dir(m)»«m.baseName».cpp
		  	«userSourcePath(m)»
		  «ENDFOR»
		)
		target_include_directories(${RSAML_TARGET} PRIVATE gen src)
		target_link_libraries(${RSAML_TARGET} PRIVATE Threads::Threads)
		# Every source includes the runtime's header: compiled once, it halves the build time.
		target_precompile_headers(${RSAML_TARGET} PRIVATE gen/rsaml/runtime.hpp)
		include(src/user.cmake OPTIONAL)
	'''

	def private messages() '''
		// «banner»
		// The structured data types of the architecture; each is yours, in src/msg/.
		#pragma once

		«FOR t : cppNames.messageStructs»
			#include "«t.cppHeader»"
		«ENDFOR»
	'''

	def private userMessage(MessageStruct t) '''
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

	def private architectureHeader() '''
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

	def private architectureSource() '''
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

	def private main() '''
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

	def private baseHeader(PlannedModule m) '''
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
		  	/** Called on each arrival at «doc(p.name)», before the module reacts. */
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

	def private baseSource(PlannedModule m) '''
		// «banner»
		#include "«m.layerId»/«m.baseName».hpp"

		namespace «ns(m)» {

		«m.baseName»::«m.baseName»(::rsaml::System& system)
		    : ::rsaml::Module(system, «str(m.qualifiedName)»«IF m.core >= 0», «m.core»«ENDIF»)«FOR p : m.inputs»,
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

	def private userCmake() '''
		# Yours: created once by RsaML, never overwritten; the generated CMakeLists.txt includes it.
		# Add sources, libraries and options to the target ${RSAML_TARGET} here, for example:
		#   target_sources(${RSAML_TARGET} PRIVATE src/planner/Geometry.cpp)
		#   target_link_libraries(${RSAML_TARGET} PRIVATE Eigen3::Eigen)
	'''

	def private readme() '''
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
