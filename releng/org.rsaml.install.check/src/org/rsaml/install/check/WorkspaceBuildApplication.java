/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.install.check;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectDescription;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.resources.IWorkspaceDescription;
import org.eclipse.core.resources.IncrementalProjectBuilder;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.equinox.app.IApplication;
import org.eclipse.equinox.app.IApplicationContext;
import org.osgi.framework.FrameworkUtil;
import org.rsaml.tests.support.ExpectedFinding;

/**
 * Builds a workspace holding one RsaML project, as Eclipse does after a user creates it, and checks the RsaML
 * problem markers against the rule, line and severity of each finding the model states in its
 * {@code <!-- expect: ... -->} comments. Exit code 0 when everything holds, 1 otherwise (each failed check printed
 * on standard error).
 * <p>
 * Arguments: {@code -model FILE} the model to put in the project; optionally {@code -expectBundle ID=VERSION}:
 * exactly one bundle ID is installed, at VERSION.
 */
public class WorkspaceBuildApplication implements IApplication {

    static final String NATURE = "org.rsaml.ide.rsamlNature";
    static final String MARKER = "org.rsaml.ide.problem";
    static final String RULE_ID = "ruleId";

    private final List<String> failures = new ArrayList<>();

    @Override
    public Object start(IApplicationContext context) throws Exception {
        Map<String, String> args = arguments((String[]) context.getArguments().get(IApplicationContext.APPLICATION_ARGS));
        checkRsamlBundlesResolve();
        if (args.containsKey("-expectBundle")) {
            checkSingleBundle(args.get("-expectBundle"));
        }
        if (failures.isEmpty()) {
            checkMarkers(Path.of(args.get("-model")));
        }
        failures.forEach(f -> System.err.println("INSTALL CHECK FAILED: " + f));
        return failures.isEmpty() ? IApplication.EXIT_OK : Integer.valueOf(1);
    }

    private void checkRsamlBundlesResolve() {
        int found = InstalledBundles.checkResolve(WorkspaceBuildApplication::isInstalledRsaml, failures);
        System.out.println("RsaML bundles installed: " + found);
        if (found == 0) {
            failures.add("no RsaML bundle is installed");
        }
    }

    /** RsaML's bundles, not the check's own (this application and the test support it reads expectations with). */
    private static boolean isInstalledRsaml(String id) {
        return id.startsWith("org.rsaml.") && !id.startsWith("org.rsaml.install.") && !id.startsWith("org.rsaml.tests.");
    }

    private void checkSingleBundle(String expected) {
        String id = expected.substring(0, expected.indexOf('='));
        String version = expected.substring(expected.indexOf('=') + 1);
        List<String> versions = Arrays.stream(context().getBundles()).filter(b -> id.equals(b.getSymbolicName()))
                .map(b -> b.getVersion().toString()).toList();
        System.out.println(id + " installed: " + versions);
        if (!versions.equals(List.of(version))) {
            failures.add("expected exactly " + id + " " + version + " (the one installed before RsaML), found " + versions);
        }
    }

    private void checkMarkers(Path model) throws CoreException, java.io.IOException {
        TreeSet<String> expected = new TreeSet<>();
        for (ExpectedFinding finding : ExpectedFinding.of(model)) {
            expected.add(finding.ruleId() + "@" + finding.line() + " " + finding.severity());
        }
        if (expected.isEmpty()) {
            failures.add(model + " states no finding in an <!-- expect: ... --> comment; nothing to check the markers against");
            return;
        }
        IWorkspace workspace = ResourcesPlugin.getWorkspace();
        if (workspace.getNatureDescriptor(NATURE) == null) {
            failures.add("the RsaML project nature " + NATURE + " is not installed");
            return;
        }
        IWorkspaceDescription settings = workspace.getDescription();
        settings.setAutoBuilding(false);
        workspace.setDescription(settings);

        IProject project = workspace.getRoot().getProject("rsaml-install-check");
        if (project.exists()) {
            project.delete(true, true, null);
        }
        project.create(null);
        project.open(null);
        // As Configure > Add RsaML Nature does: setting the description configures the nature, which adds its builder.
        IProjectDescription description = project.getDescription();
        description.setNatureIds(new String[] { NATURE });
        project.setDescription(description, null);
        if (project.getDescription().getBuildSpec().length == 0) {
            failures.add("the RsaML nature added no builder to the project");
            return;
        }
        IFile file = project.getFile(model.getFileName().toString());
        try (InputStream in = Files.newInputStream(model)) {
            file.create(in, true, null);
        }
        workspace.build(IncrementalProjectBuilder.FULL_BUILD, null);

        TreeSet<String> actual = new TreeSet<>();
        for (IMarker marker : file.findMarkers(MARKER, true, org.eclipse.core.resources.IResource.DEPTH_ZERO)) {
            String finding = marker.getAttribute(RULE_ID, "?") + "@" + marker.getAttribute(IMarker.LINE_NUMBER, -1) + " "
                    + severity(marker.getAttribute(IMarker.SEVERITY, -1));
            System.out.println("marker " + finding + ": " + marker.getAttribute(IMarker.MESSAGE, ""));
            actual.add(finding);
        }
        if (!actual.equals(expected)) {
            failures.add("RsaML markers on " + file.getFullPath() + " are " + actual + ", expected " + expected);
        }
        IMarker[] problems = project.findMarkers(IMarker.PROBLEM, true, org.eclipse.core.resources.IResource.DEPTH_INFINITE);
        for (IMarker problem : problems) {
            if (!MARKER.equals(problem.getType())) {
                failures.add("unexpected problem " + problem.getType() + ": " + problem.getAttribute(IMarker.MESSAGE, ""));
            }
        }
        workspace.save(true, null);
    }

    /** The marker severity as the expect comments name it. */
    private static String severity(int markerSeverity) {
        return switch (markerSeverity) {
            case IMarker.SEVERITY_ERROR -> "error";
            case IMarker.SEVERITY_WARNING -> "warning";
            case IMarker.SEVERITY_INFO -> "info";
            default -> "severity " + markerSeverity;
        };
    }

    private static Map<String, String> arguments(String[] args) {
        Map<String, String> map = new java.util.HashMap<>();
        for (int i = 0; i + 1 < args.length; i += 2) {
            map.put(args[i], args[i + 1]);
        }
        for (String required : List.of("-model")) {
            if (!map.containsKey(required)) {
                throw new IllegalArgumentException("missing argument " + required + " (arguments: " + Arrays.toString(args) + ")");
            }
        }
        return map;
    }

    private org.osgi.framework.BundleContext context() {
        return FrameworkUtil.getBundle(getClass()).getBundleContext();
    }

    @Override
    public void stop() {
        // Runs to completion.
    }
}
