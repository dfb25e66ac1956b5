/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.IJobManager;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.transaction.RecordingCommand;
import org.eclipse.emf.transaction.TransactionalEditingDomain;
import org.eclipse.jface.preference.IPreferenceStore;
import org.eclipse.sirius.business.api.componentization.ViewpointRegistry;
import org.eclipse.sirius.business.api.dialect.DialectManager;
import org.eclipse.sirius.business.api.modelingproject.AbstractRepresentationsFileJob;
import org.eclipse.sirius.business.api.modelingproject.ModelingProject;
import org.eclipse.sirius.business.api.preferences.SiriusPreferencesKeys;
import org.eclipse.sirius.business.api.session.Session;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.tools.api.SiriusPlugin;
import org.eclipse.sirius.ui.business.api.preferences.SiriusUIPreferencesKeys;
import org.eclipse.sirius.ui.business.api.viewpoint.ViewpointSelectionCallback;
import org.eclipse.sirius.ui.tools.api.project.ModelingProjectManager;
import org.eclipse.sirius.business.api.query.DRepresentationQuery;
import org.eclipse.sirius.viewpoint.DRepresentation;
import org.eclipse.sirius.viewpoint.DSemanticDecorator;
import org.eclipse.sirius.viewpoint.description.RepresentationDescription;
import org.eclipse.sirius.viewpoint.description.Viewpoint;
import org.eclipse.sirius.viewpoint.provider.SiriusEditPlugin;
import org.eclipse.swt.widgets.Display;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.TestRepository;

/**
 * A modeling project as a user makes one: created by Sirius, holding copies of examples as semantic
 * resources of its session, with the RsaML viewpoint enabled. Every change goes through the session's
 * command stack, as the diagram editor's own do.
 * <p>
 * The project's changes stay in memory: Sirius's save of a session in the background after each change made while no
 * editor of it is open ({@link SiriusUIPreferencesKeys#PREF_SAVE_WHEN_NO_EDITOR}), and its return to the last save when
 * the last editor closes, which goes with it ({@link SiriusUIPreferencesKeys#PREF_RELOAD_ON_LAST_EDITOR_CLOSE}), are
 * off, as Sirius's own tests have them. That save runs outside any transaction and, while it compares the
 * representations file with the file on disk, turns off that resource's notifications: a diagram created meanwhile
 * was added to the file unseen by the session (neither the editing domain's change recorder nor Sirius's
 * cross-referencer attached to it), so deleting an element left its node on that diagram and, opened, the diagram was
 * drawn without following its own arrangement. Two such saves in a row can also be taken for a change made outside
 * Eclipse, whose question (reload the file?) waits for an answer nobody gives. A user takes longer between two
 * changes than that save; a test does not. Every diagram created is checked to be seen by the session.
 */
final class SiriusProject {

    static final NullProgressMonitor MONITOR = new NullProgressMonitor();

    final IProject project;
    final Session session;
    final Viewpoint viewpoint;

    private SiriusProject(IProject project, Session session, Viewpoint viewpoint) {
        this.project = project;
        this.session = session;
        this.viewpoint = viewpoint;
    }

    static SiriusProject create(String name, List<String> examples) throws Exception {
        // What a user turns on so that open diagrams follow every model change (Sirius's default is off).
        InstanceScope.INSTANCE.getNode(SiriusPlugin.ID).putBoolean(SiriusPreferencesKeys.PREF_AUTO_REFRESH.name(), true);
        // No save in the background, no return to the last save (see the class comment).
        IPreferenceStore siriusUi = SiriusEditPlugin.getPlugin().getPreferenceStore();
        siriusUi.setValue(SiriusUIPreferencesKeys.PREF_SAVE_WHEN_NO_EDITOR.name(), false);
        siriusUi.setValue(SiriusUIPreferencesKeys.PREF_RELOAD_ON_LAST_EDITOR_CLOSE.name(), false);
        IProject project = ModelingProjectManager.INSTANCE.createNewModelingProject(name, true, MONITOR);
        Session session = ModelingProject.asModelingProject(project).get().getSession();
        assertNotNull(session, "the modeling project opens a Sirius session");
        Viewpoint viewpoint = ViewpointRegistry.getInstance().getViewpoints().stream().filter(v -> "RsaML".equals(v.getName())).findFirst()
                .orElseThrow(() -> new AssertionError("the RsaML viewpoint is registered"));
        SiriusProject result = new SiriusProject(project, session, viewpoint);
        for (String example : examples) {
            IFile file = project.getFile(example);
            try (InputStream in = Files.newInputStream(TestRepository.example(example))) {
                file.create(in, true, MONITOR);
            }
        }
        // Sirius attaches the models added to a modeling project to its session in a job of its own, scheduled when the
        // workspace reports the new files. That report may come later than file.create (the workspace defers it while it
        // is still reporting an earlier change, e.g. the representations file being saved): the project is set up once
        // Sirius has attached every model itself. Attaching them here instead would leave Sirius's job to attach them
        // again later, under the first diagram opened, which Sirius then draws again from scratch, unarranged.
        result.awaitAttached(examples.stream().map(result::uri).toList());
        result.execute(new RecordingCommand(result.domain(), "enable the RsaML viewpoint") {
            @Override
            protected void doExecute() {
                new ViewpointSelectionCallback().selectViewpoint(viewpoint, session, MONITOR);
            }
        });
        assertTrue(session.getSelectedViewpoints(false).stream().anyMatch(v -> "RsaML".equals(v.getName())),
                "the RsaML viewpoint is enabled in the project: " + session.getSelectedViewpoints(false));
        return result;
    }

    /** How long Sirius may take to attach the models copied into the project to its session. */
    private static final long ATTACH_TIMEOUT_SECONDS = 120;

    /**
     * Whether the workspace's build of the models just copied in (RsaML's builder marks their findings) is still to come
     * or running: the project is ready once it is done, as for a user who opens diagrams after the build, so that no
     * test step runs under it. (The unarranged first diagram once put down to this build came from Sirius's background
     * save; see the class comment.)
     */
    private static boolean building() {
        return Job.getJobManager().find(org.eclipse.core.resources.ResourcesPlugin.FAMILY_AUTO_BUILD).length > 0
                || Job.getJobManager().find(org.eclipse.core.resources.ResourcesPlugin.FAMILY_MANUAL_BUILD).length > 0;
    }

    /** Waits until Sirius has attached each of {@code uris} to the session and none of its jobs on representations files is left. */
    private void awaitAttached(List<URI> uris) throws InterruptedException {
        long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(ATTACH_TIMEOUT_SECONDS);
        while (true) {
            awaitRepresentationsFileJobs();
            List<URI> missing = uris.stream().filter(u -> session.getSemanticResources().stream().noneMatch(r -> r.getURI().equals(u))).toList();
            if (missing.isEmpty() && Job.getJobManager().find(AbstractRepresentationsFileJob.FAMILY).length == 0 && !building()) {
                return;
            }
            if (System.nanoTime() > deadline) {
                throw new AssertionError("Sirius has not attached " + missing + " to the session of " + project.getName() + " (or the workspace is still building: " + building() + ") within "
                        + ATTACH_TIMEOUT_SECONDS + " s of their creation in the modeling project (attached: "
                        + session.getSemanticResources().stream().map(Resource::getURI).toList() + ")");
            }
            Thread.sleep(50);
        }
    }

    /**
     * Waits until no job of Sirius's on representations files (opening a session, attaching semantic resources) is
     * scheduled or running, dispatching the display's events meanwhile (those jobs may need the UI thread).
     */
    static void awaitRepresentationsFileJobs() throws InterruptedException {
        awaitJobs(AbstractRepresentationsFileJob.FAMILY);
    }

    /** How long Sirius's jobs on a representations file (opening its session, attaching models) may take. */
    private static final long JOBS_TIMEOUT_SECONDS = 120;

    /** Waits until no job of {@code family} is scheduled or running, dispatching the display's events meanwhile (those jobs may need the UI thread). */
    private static void awaitJobs(Object family) throws InterruptedException {
        IJobManager jobs = Job.getJobManager();
        Display display = Display.getCurrent();
        if (display == null) {
            jobs.join(family, MONITOR);
            return;
        }
        long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(JOBS_TIMEOUT_SECONDS);
        JobChangeAdapter wake = new JobChangeAdapter() {
            @Override
            public void done(IJobChangeEvent event) {
                if (event.getJob().belongsTo(family)) {
                    display.wake();
                }
            }
        };
        jobs.addJobChangeListener(wake);
        try {
            while (jobs.find(family).length > 0) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("Sirius's jobs " + List.of(jobs.find(family)) + " (" + family + ") have not ended within " + JOBS_TIMEOUT_SECONDS + " s");
                }
                if (!display.readAndDispatch()) {
                    // The job's end wakes the display; the timer bounds the sleep should it end before the display sleeps.
                    display.timerExec(100, () -> { });
                    display.sleep();
                }
            }
        } finally {
            jobs.removeJobChangeListener(wake);
        }
        flushEvents();
    }

    void delete() throws Exception {
        session.close(MONITOR);
        project.delete(true, true, MONITOR);
    }

    private URI uri(String example) {
        return URI.createPlatformResourceURI(project.getFile(example).getFullPath().toString(), true);
    }

    TransactionalEditingDomain domain() {
        return session.getTransactionalEditingDomain();
    }

    void execute(Command command) {
        domain().getCommandStack().execute(command);
        flushEvents();
    }

    /** Undoes the last change, as Edit &gt; Undo does. */
    void undo() {
        domain().getCommandStack().undo();
        flushEvents();
    }

    void run(String label, Runnable change) {
        execute(new RecordingCommand(domain(), label) {
            @Override
            protected void doExecute() {
                change.run();
            }
        });
    }

    static void flushEvents() {
        Display display = Display.getCurrent();
        if (display != null) {
            while (display.readAndDispatch()) {
                // let Sirius's refresh, layout and decorators run
            }
        }
    }

    Architecture architecture(String example) {
        URI uri = uri(example);
        Resource resource = session.getSemanticResources().stream().filter(r -> r.getURI().equals(uri)).findFirst()
                .orElseThrow(() -> new AssertionError(example + " is a semantic resource of the session"));
        return (Architecture) resource.getContents().get(0);
    }

    /** The description as the session has it (its own copy of the viewpoint, which representations are made from). */
    RepresentationDescription description(String name) {
        Viewpoint selected = session.getSelectedViewpoints(false).stream().filter(v -> "RsaML".equals(v.getName())).findFirst()
                .orElseThrow(() -> new AssertionError("the RsaML viewpoint is enabled: open " + session.isOpen() + ", selected "
                        + session.getSelectedViewpoints(false) + ", sessions " + org.eclipse.sirius.business.api.session.SessionManager.INSTANCE.getSessions()));
        return selected.getOwnedRepresentations().stream().filter(r -> r.getName().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("the RsaML viewpoint has the " + name + " diagram"));
    }

    DDiagram create(String descriptionName, EObject root, String name) {
        DRepresentation[] created = new DRepresentation[1];
        run("create " + name, () -> created[0] = DialectManager.INSTANCE.createRepresentation(name, root, description(descriptionName), session, MONITOR));
        assertNotNull(created[0], "Sirius creates the " + descriptionName + " diagram " + name);
        assertTrue(seenBySession(created[0]), "the " + descriptionName + " diagram " + name + " is seen by the session (Sirius's cross-referencer knows it"
                + " draws " + RsamlLabels.qualifiedName(root) + "): a diagram added unseen keeps the nodes of deleted elements and does not follow its"
                + " changes; adapters of the diagram: " + created[0].eAdapters());
        return (DDiagram) created[0];
    }

    /**
     * Whether the session sees the representation as it sees the models: Sirius's semantic cross-referencer, through
     * which it finds the nodes to delete with an element (and the change recorder undo needs, attached alike), knows the
     * representation's reference to the element it draws.
     */
    private boolean seenBySession(DRepresentation representation) {
        EObject target = ((DSemanticDecorator) representation).getTarget();
        return session.getSemanticCrossReferencer().getInverseReferences(target).stream().anyMatch(s -> s.getEObject() == representation);
    }

    /** Deletes a representation, so that later diagrams of the same element draw no link to it. */
    void delete(DRepresentation representation) {
        var descriptor = new DRepresentationQuery(representation).getRepresentationDescriptor();
        run("delete " + descriptor.getName(), () -> DialectManager.INSTANCE.deleteRepresentation(descriptor, session));
    }

    String evaluate(EObject target, String expression) {
        try {
            return session.getInterpreter().evaluateString(target, expression);
        } catch (Exception e) {
            throw new AssertionError("cannot evaluate " + expression + " on " + target, e);
        }
    }
}
