/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp

import java.io.IOException
import java.io.UncheckedIOException
import java.nio.charset.StandardCharsets
import java.util.List
import org.rsaml.generator.internal.Templates
import org.rsaml.generator.internal.cxx.CxxCode
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.internal.cxx.UserCode
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.generator.spi.GeneratedFile
import org.rsaml.generator.spi.GeneratedProject
import org.rsaml.generator.spi.OutputContext
import org.rsaml.generator.spi.TargetGenerator

/**
 * The C++17 target: a CMake project with one class per module. The generated part of each module
 * (gen/LAYER/ModuleBase.*) declares its typed ports, runs its functions and is regenerated; the
 * architect's part (src/LAYER/Module.*) implements the actions and is created once. The runtime
 * (gen/rsaml/) is the same for every model: the files runtime/cpp/rsaml/* of this bundle (RUNTIME_HEADERS,
 * RUNTIME_SOURCES), and the headers of runtime/cxx/rsaml/ (SHARED_RUNTIME_HEADERS), which the ROS 2 nodes share.
 * Each output file has its template: CppModuleTemplate, CppArchitectureTemplate, CppCmakeTemplate,
 * CppMessagesTemplate, CppReadmeTemplate, and the user code every C++ target shares (cxx.UserCode).
 */
class CppTarget implements TargetGenerator {

	/**
	 * The C++ runtime's headers in runtime/cpp/rsaml/ of this bundle: runtime.hpp, which generated code includes,
	 * and the headers of its parts, which it includes. Every project carries them in gen/rsaml/.
	 */
	public static val List<String> RUNTIME_HEADERS = #["runtime.hpp", "clock.hpp", "options.hpp", "trace.hpp", "measure.hpp", "module.hpp",
		"ports.hpp", "system.hpp", "internal.hpp"]

	/**
	 * The headers in runtime/cxx/rsaml/ of this bundle that the C++ runtime and the ROS 2 nodes share (EDF's
	 * SCHED_DEADLINE, the job summary line's writer, the trace's queue and its writer thread): every C++ project and ROS 2
	 * runtime package carries them in gen/rsaml/.
	 */
	public static val List<String> SHARED_RUNTIME_HEADERS = #["realtime.hpp", "jobs.hpp", "tracequeue.hpp"]

	/** The C++ runtime's sources in runtime/cpp/rsaml/ of this bundle, one per concern; each project's CMake build compiles them. */
	public static val List<String> RUNTIME_SOURCES = #["options.cpp", "clock.cpp", "trace.cpp", "measure.cpp", "module.cpp", "system.cpp",
		"scheduling.cpp"]

	override id() {
		"cpp"
	}

	override description() {
		"a CMake C++17 project that builds and runs on its own (threads, timers, a trace of the run)"
	}

	override generate(ExecutionPlan plan, OutputContext output) {
		val warnings = <String>newArrayList
		val project = CxxNames.stableProject(plan, output.kept, warnings, "the C++ namespace, the CMake project and the program", false)
		warnings += Templates.readmeLink(output, "the program, the modules and their files, the files that are yours")
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

/** The files of one plan: which file each template writes, and where. */
class CppFiles {

	val ExecutionPlan plan
	val extension CxxNames names
	val String banner
	val UserCode userCode
	val CppModuleTemplate module
	val CppArchitectureTemplate architecture
	val CppCmakeTemplate cmake
	val CppMessagesTemplate messages

	new(ExecutionPlan plan, String project) {
		this.plan = plan
		this.names = new CxxNames(plan, project)
		this.banner = Templates.banner(plan)
		this.module = new CppModuleTemplate(plan, names)
		this.architecture = new CppArchitectureTemplate(plan, names)
		this.cmake = new CppCmakeTemplate(plan, names)
		this.messages = new CppMessagesTemplate(plan, names)
		val cppNames = new CppNames(plan, names)
		this.userCode = new UserCode(names, "Module",
			"declares the ports and runs the functions; implement the actions and\n// input handlers here.",
			"Inputs: in_<port>.value() is the latest value. Outputs: set out_<port>.value; it is sent after\neach activation of the module (or call out_<port>.send() to send at once).",
			"value", [cppNames.cppType(it)])
	}

	def files() {
		val files = <GeneratedFile>newArrayList
		files += GeneratedFile.generated("CMakeLists.txt", cmake.cmake)
		for (f : CppTarget.RUNTIME_HEADERS + CppTarget.RUNTIME_SOURCES) {
			files += GeneratedFile.generated("gen/rsaml/" + f, "// " + banner + "\n" + CppTarget.runtimeFile("rsaml/" + f))
		}
		for (f : CppTarget.SHARED_RUNTIME_HEADERS) {
			files += GeneratedFile.generated("gen/rsaml/" + f, "// " + banner + "\n" + CppTarget.runtimeFile("cxx", "rsaml/" + f))
		}
		files += GeneratedFile.generated("gen/messages.hpp", messages.messages)
		files += GeneratedFile.generated("gen/Architecture.hpp", architecture.architectureHeader)
		files += GeneratedFile.generated("gen/Architecture.cpp", architecture.architectureSource)
		files += GeneratedFile.generated("gen/main.cpp", architecture.main)
		for (m : plan.modules) {
			files += GeneratedFile.generated(module.baseHeaderPath(m).toString, module.baseHeader(m))
			files += GeneratedFile.generated(module.dir(m) + m.baseName + ".cpp", module.baseSource(m))
			files += GeneratedFile.user("src/" + m.layerId + "/" + m.className + ".hpp", userCode.header(m), m.hooks, m.stubs, CxxCode.IDENTIFIERS)
			files += GeneratedFile.user(module.userSourcePath(m).toString, userCode.source(m))
		}
		for (t : messages.structs) {
			files += GeneratedFile.user("src/" + t.cppHeader, messages.userMessage(t))
		}
		files += GeneratedFile.user("src/user.cmake", cmake.userCmake)
		val readme = new CppReadmeTemplate(plan, names)
		files += GeneratedFile.user(Templates.README, readme.readme)
		files += GeneratedFile.generated(Templates.GENERATED_README, readme.generated)
		files
	}
}
