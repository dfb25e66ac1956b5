/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import java.util.List
import java.util.TreeSet
import org.rsaml.analysis.plan.ExecutionPlan
import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.generator.internal.cpp.CppTarget
import org.rsaml.generator.internal.cxx.CxxCode
import org.rsaml.generator.internal.cxx.CxxNames
import org.rsaml.generator.spi.GeneratedFile
import org.rsaml.generator.spi.GeneratedProject
import org.rsaml.generator.spi.OutputContext
import org.rsaml.generator.spi.TargetGenerator

/**
 * The ROS 2 target: an ament_cmake package whose nodes (one per module) are rclcpp components of
 * one shared library, each with a publisher per output port and a subscription per entry port on
 * relative topics (connected ports share one), a timer per timed release on the node's clock, the
 * model's times as parameters, subsumption links as extra subscriptions, and launch files for one
 * process or a process per node; plus an interfaces package for the structured message types the
 * model names without a ROS package. The nodes derive from the scheduling runtime (gen/rsaml/, the
 * files runtime/ros2/rsaml/* of this bundle): each timed release on an executor thread of its own at
 * the analysis's real-time priority, in the package's component container or a node's own process.
 * Same generation gap as the C++ target: gen/ and the build
 * files are regenerated; src/, the .msg files, user.cmake, package.user.xml and
 * config/&lt;pkg&gt;.params.yaml are the architect's (gen/&lt;pkg&gt;.params.yaml is its current form).
 * Each output file has its template: Ros2NodeTemplate (with Ros2ManagedNodeTemplate for a managed
 * node), Ros2ComponentTemplate, Ros2CmakeTemplate, Ros2PackageTemplate, Ros2LaunchTemplate,
 * Ros2LaunchTestTemplate, Ros2ParamsTemplate, Ros2UserTemplate, Ros2ReadmeTemplate (README.md, the
 * architect's, and GENERATED.md, regenerated).
 */
class Ros2Target implements TargetGenerator {

	/**
	 * The scheduling runtime's library in runtime/ros2/rsaml/ of this bundle: its headers, which the nodes include,
	 * and its sources, compiled into the shared library the nodes of a process share.
	 */
	public static val List<String> RUNTIME_HEADERS = #["scheduling.hpp", "usage.hpp"]
	public static val List<String> RUNTIME_SOURCES = #["scheduling.cpp"]

	/** The component container's source in runtime/ros2/rsaml/; the launch files start it. */
	public static val String CONTAINER_SOURCE = "container.cpp"

	/** What managed nodes add in runtime/ros2/rsaml/: the header of their base class, and the lifecycle manager's source. */
	public static val List<String> LIFECYCLE_HEADERS = #["lifecycle.hpp"]
	public static val String LIFECYCLE_MANAGER_SOURCE = "lifecycle_manager.cpp"

	/** Every file of runtime/ros2/rsaml/ a package carries in gen/rsaml/; the lifecycle's when some node is {@code managed}. */
	def static List<String> runtimeFiles(boolean managed) {
		val files = newArrayList
		files += RUNTIME_HEADERS
		files += RUNTIME_SOURCES
		files += CONTAINER_SOURCE
		if (managed) {
			files += LIFECYCLE_HEADERS
			files += LIFECYCLE_MANAGER_SOURCE
		}
		files
	}

	override id() {
		"ros2"
	}

	override description() {
		"ament_cmake packages for ROS 2 (rclcpp components): a node per module, topics, launch files"
	}

	override generate(ExecutionPlan plan, OutputContext output) {
		val warnings = <String>newArrayList
		val project = CxxNames.stableProject(plan, output.kept, warnings, "the ROS package, the interfaces package and the C++ namespace", true)
		val context = new Ros2Context(plan, project, output)
		warnings += context.packages.warnings
		warnings += context.packages.checkUserCodeIsHere(plan, context.names, output)
		val files = new Ros2Files(context)
		for (cycle : plan.reactiveCycles) {
			warnings += "modules " + cycle.map[qualifiedName].join(" -> ")
				+ " react to each other's data in a cycle; ROS 2 messages carry no wave, so each of them reacts at most once per "
				+ cycle.map[files.cycleBound(it)].join(", ")
				+ " (the shortest period that feeds the cycle; parameter " + cycle.map[context.reactionParameter(it).name].toSet.join(", ") + ")"
		}
		val paramsTemplate = new Ros2ParamsTemplate(context)
		val params = paramsTemplate.path
		output.userFile(params).ifPresent[warnings += Ros2ParamsCheck.check(params, it, context.modelParameters, paramsTemplate.currentPath)]
		for (m : plan.modules.filter[!inputs.empty]) {
			val inputs = new java.util.LinkedHashMap<String, String>
			m.inputs.forEach[inputs.put(context.names.inName(it), context.names.onName(it))]
			for (path : Ros2Packages.userFiles(context.nodePackage(m), context.names, m)) {
				output.userFile(path).ifPresent[warnings += Ros2UserCodeCheck.valueReads(path, it, inputs)]
			}
		}
		output.userFile("README.md").filter[!contains(Ros2ReadmeTemplate.GENERATED)].ifPresent[
			warnings += "README.md (yours, kept as it is) does not link " + Ros2ReadmeTemplate.GENERATED + ", which generating rewrites every"
				+ " time with what it made of the model (the package layout, the nodes, topics, parameters and managed nodes, the files"
				+ " that are yours): what your README says of them is as of when it was written; link " + Ros2ReadmeTemplate.GENERATED
				+ " from it (or delete README.md to have it created again)"
		]
		new GeneratedProject(files.files, warnings, #{CxxNames.KEPT_PROJECT -> project, Ros2Packages.KEPT_LAYOUT -> plan.architecture.packages.literal})
	}
}

/** The files of one plan: which file each template writes, and where. */
class Ros2Files {

	val Ros2Context context
	val extension CxxNames names
	val extension Ros2Names rosNames
	val String pkg

	new(Ros2Context context) {
		this.context = context
		this.names = context.names
		this.rosNames = context.rosNames
		this.pkg = context.pkg
	}

	def cycleBound(PlannedModule m) {
		Ros2Names.duration(rosNames.cycleBoundNs(m))
	}

	def files() {
		val node = new Ros2NodeTemplate(context)
		val component = new Ros2ComponentTemplate(context)
		val cmake = new Ros2CmakeTemplate(context)
		val manifests = new Ros2PackageTemplate(context)
		val launch = new Ros2LaunchTemplate(context)
		val user = new Ros2UserTemplate(context)
		val files = <GeneratedFile>newArrayList
		val packages = context.packages
		if (packages.single) {
			files += GeneratedFile.generated(pkg + "/package.xml", manifests.packageXml(context.manifest(pkg)))
			files += GeneratedFile.generated(pkg + "/CMakeLists.txt", cmake.cmake)
		} else {
			files += GeneratedFile.generated(pkg + "/package.xml", manifests.systemPackageXml(context.manifest(pkg)))
			files += GeneratedFile.generated(pkg + "/CMakeLists.txt", cmake.systemCmake)
			val rpkg = packages.runtime
			files += GeneratedFile.generated(rpkg + "/package.xml", manifests.runtimePackageXml(context.manifest(rpkg)))
			files += GeneratedFile.user(rpkg + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(rpkg))
			files += GeneratedFile.generated(rpkg + "/CMakeLists.txt", cmake.runtimeCmake)
			files += GeneratedFile.user(rpkg + "/user.cmake", cmake.runtimeUserCmake)
			for (np : packages.nodePackages) {
				files += GeneratedFile.generated(np.name + "/package.xml", manifests.nodesPackageXml(np, context.manifest(np.name)))
				files += GeneratedFile.user(np.name + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(np.name))
				files += GeneratedFile.generated(np.name + "/CMakeLists.txt", cmake.nodesCmake(np))
				files += GeneratedFile.user(np.name + "/user.cmake", cmake.userCmake)
			}
		}
		files += GeneratedFile.user(pkg + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(pkg))
		files += GeneratedFile.user(pkg + "/user.cmake", if (packages.single) cmake.userCmake else cmake.systemUserCmake)
		val params = new Ros2ParamsTemplate(context)
		files += GeneratedFile.user(params.path, params.params)
		files += GeneratedFile.generated(params.currentPath, params.current)
		files += GeneratedFile.generated(pkg + "/launch/" + pkg + ".launch.py", launch.composed)
		files += GeneratedFile.generated(pkg + "/launch/" + pkg + "_processes.launch.py", launch.processes)
		val launchTest = new Ros2LaunchTestTemplate(context)
		files += GeneratedFile.generated(pkg + "/" + launchTest.path, launchTest.launchTest)
		if (!packages.single) {
			for (np : packages.nodePackages) {
				files += GeneratedFile.generated(np.name + "/" + launchTest.path(np), launchTest.packageTest(np))
			}
		}
		val rpkg = packages.runtime
		for (f : Ros2Target.runtimeFiles(!rosNames.managedModules.empty)) {
			files += GeneratedFile.generated(rpkg + "/gen/rsaml/" + f, runtimeFile(f))
		}
		for (f : CppTarget.SHARED_RUNTIME_HEADERS) {
			files += GeneratedFile.generated(rpkg + "/gen/rsaml/" + f, "// " + context.banner + "\n" + CppTarget.runtimeFile("cxx", "rsaml/" + f))
		}
		for (m : context.plan.modules) {
			val npkg = context.nodePackage(m)
			files += GeneratedFile.generated(npkg + "/gen/" + m.layerId + "/" + m.baseName + ".hpp", node.base(m))
			files += GeneratedFile.generated(npkg + "/gen/" + m.layerId + "/" + m.className + "Component.cpp", component.component(m))
			files += GeneratedFile.generated(npkg + "/gen/" + m.layerId + "/" + m.mainName + ".cpp", component.nodeMain(m))
			val sources = Ros2Packages.userFiles(npkg, names, m)
			files += GeneratedFile.user(sources.get(0), user.header(m), m.hooks, m.stubs, CxxCode.IDENTIFIERS)
			files += GeneratedFile.user(sources.get(1), user.source(m))
		}
		val messages = context.generatedMessages
		if (!messages.empty) {
			val ipkg = rosNames.interfacesPackage
			val imanifest = context.manifest(ipkg)
			val deps = new TreeSet<String>
			for (t : messages) {
				context.output.userFile(ipkg + "/msg/" + t.rosName + ".msg").ifPresent[deps += Ros2Manifest.messageDependencies(it, ipkg)]
			}
			deps += imanifest.buildDependencies
			deps -= ipkg
			files += GeneratedFile.generated(ipkg + "/package.xml", manifests.interfacesPackageXml(imanifest, deps))
			files += GeneratedFile.user(ipkg + "/" + Ros2Manifest.FILE, Ros2Manifest.initialText(ipkg))
			files += GeneratedFile.user(ipkg + "/user.cmake", cmake.interfacesUserCmake)
			files += GeneratedFile.generated(ipkg + "/CMakeLists.txt", cmake.interfacesCmake(deps))
			for (t : messages) {
				files += GeneratedFile.user(ipkg + "/msg/" + t.rosName + ".msg", user.message(t))
			}
		}
		val readme = new Ros2ReadmeTemplate(context)
		files += GeneratedFile.user("README.md", readme.readme)
		files += GeneratedFile.generated(Ros2ReadmeTemplate.GENERATED, readme.generated)
		files
	}

	/**
	 * A file of the scheduling runtime (runtime/ros2/rsaml/ of this bundle), in the package's
	 * namespace, so that the libraries of two packages can share a process.
	 */
	def private runtimeFile(String file) {
		val in = Ros2Target.getResourceAsStream("/runtime/ros2/rsaml/" + file)
		if (in === null) {
			throw new IllegalStateException("the ROS 2 runtime file " + file + " is missing from org.rsaml.generator")
		}
		val text = try new String(in.readAllBytes, java.nio.charset.StandardCharsets.UTF_8) finally in.close
		"// " + context.banner + "\n" + text.replace("namespace rsaml_ros2 {", "namespace " + names.project + "::rsaml_ros2 {")
			.replace("}  // namespace rsaml_ros2", "}  // namespace " + names.project + "::rsaml_ros2")
			.replaceAll("(?<![\\w:])rsaml_ros2::", names.project + "::rsaml_ros2::")
	}
}
