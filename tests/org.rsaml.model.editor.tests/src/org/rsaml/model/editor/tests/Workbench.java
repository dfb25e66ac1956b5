/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.tests;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.zip.CRC32;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.OperationCanceledException;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.jface.dialogs.ProgressMonitorDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.rsaml.tests.support.TestRepository;

/** What the editor tests do with the running workbench: events, jobs, dialogs, files, screenshots. */
final class Workbench {

    /** Where the screenshots of a test run go. */
    static final Path SCREENSHOTS = TestRepository.root().resolve("tests/org.rsaml.model.editor.tests/target/screenshots");

    private Workbench() {
    }

    static Display display() {
        return PlatformUI.getWorkbench().getDisplay();
    }

    static IWorkbenchPage page() {
        return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
    }

    /** Runs the UI's pending events (layout, painting, asynchronous updates). */
    static void processEvents() {
        Display display = display();
        while (display.readAndDispatch()) {
            // keep going
        }
    }

    /** Lets the UI run until {@code condition} holds, or fails after a minute saying what was awaited. */
    static void waitUntil(String what, BooleanSupplier condition) {
        long end = System.nanoTime() + 60_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new AssertionError("waited a minute for " + what);
            }
            if (!display().readAndDispatch()) {
                display().timerExec(20, () -> { });
                display().sleep();
            }
        }
    }

    /** Waits for the jobs of a family (the auto-build, say), letting the UI run meanwhile. */
    static void join(Object family) {
        Job.getJobManager().wakeUp(family);
        waitUntil("the jobs of " + family, () -> Job.getJobManager().find(family).length == 0);
        try {
            Job.getJobManager().join(family, null);
        } catch (OperationCanceledException | InterruptedException e) {
            throw new AssertionError(e);
        }
        processEvents();
    }

    static IFile copy(IProject project, Path source, String path) throws CoreException, IOException {
        IFile file = project.getFile(path);
        if (file.getParent() instanceof IFolder folder && !folder.exists()) {
            folder.create(true, true, null);
        }
        file.create(Files.newInputStream(source), true, null);
        return file;
    }

    static IProject newProject(String name) throws CoreException {
        IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject(name);
        project.create(null);
        project.open(null);
        return project;
    }

    /**
     * Answers OK to the next dialog that opens once {@code action} ran (Validate shows its result in
     * one, after the validation, from an asynchronous runnable), after a screenshot of it; returns
     * its title, or fails when none opens.
     */
    static String closeNextDialog(Runnable action, String screenshot) {
        List<String> titles = new ArrayList<>();
        Runnable[] closer = new Runnable[1];
        closer[0] = () -> {
            for (Shell shell : display().getShells()) {
                if (shell.isVisible() && shell.getData() instanceof Dialog dialog && !(dialog instanceof ProgressMonitorDialog)) {
                    titles.add(shell.getText());
                    screenshot(shell, screenshot);
                    Button ok = shell.getDefaultButton();
                    if (ok != null) {
                        ok.notifyListeners(SWT.Selection, new Event());
                    }
                    if (!shell.isDisposed()) {
                        dialog.close();
                    }
                    return;
                }
            }
            display().timerExec(100, closer[0]);
        };
        display().timerExec(100, closer[0]);
        try {
            action.run();
            waitUntil("a dialog", () -> !titles.isEmpty());
        } finally {
            display().timerExec(-1, closer[0]);
        }
        return titles.get(0);
    }

    /** A PNG of the shell as it is on the screen, under target/screenshots/. */
    static Path screenshot(Shell shell, String name) {
        processEvents();
        return writePng(capture(shell), SCREENSHOTS.resolve(name + ".png"), null);
    }

    static ImageData capture(Shell shell) {
        Rectangle area = shell.getBounds();
        GC gc = new GC(display());
        Image image = new Image(display(), area.width, area.height);
        try {
            gc.copyArea(image, area.x, area.y);
            return image.getImageData();
        } finally {
            gc.dispose();
            image.dispose();
        }
    }

    /**
     * Writes the image as PNG; with {@code text}, a {@code tEXt} chunk {@code rsaml:shows} holding it
     * (what the picture shows, for the check that keeps the README's picture current).
     */
    static Path writePng(ImageData data, Path file, String text) {
        try {
            Files.createDirectories(file.getParent());
            ImageLoader loader = new ImageLoader();
            loader.data = new ImageData[] { data };
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            loader.save(out, SWT.IMAGE_PNG);
            byte[] png = out.toByteArray();
            Files.write(file, text == null ? png : withText(png, text));
            return file;
        } catch (IOException e) {
            throw new AssertionError("cannot write " + file, e);
        }
    }

    private static final String KEY = "rsaml:shows";

    /** The PNG with an iTXt chunk (UTF-8 text) after its header chunk (8 bytes of signature, then 25 of IHDR). */
    private static byte[] withText(byte[] png, String text) {
        byte[] keyword = KEY.getBytes(StandardCharsets.ISO_8859_1);
        byte[] utf8 = text.getBytes(StandardCharsets.UTF_8);
        // keyword, NUL, not compressed, method 0, no language tag (NUL), no translated keyword (NUL), text
        ByteBuffer body = ByteBuffer.allocate(keyword.length + 5 + utf8.length);
        body.put(keyword).put((byte) 0).put((byte) 0).put((byte) 0).put((byte) 0).put((byte) 0).put(utf8);
        ByteBuffer chunk = ByteBuffer.allocate(12 + body.capacity());
        chunk.putInt(body.capacity()).put("iTXt".getBytes(StandardCharsets.US_ASCII)).put(body.array());
        CRC32 crc = new CRC32();
        crc.update(chunk.array(), 4, 4 + body.capacity());
        chunk.putInt((int) crc.getValue());
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(png, 0, 33);
        out.write(chunk.array(), 0, chunk.capacity());
        out.write(png, 33, png.length - 33);
        return out.toByteArray();
    }

    /** The text of the PNG's {@code rsaml:shows} chunk, or {@code null}. */
    static String textOf(Path png) throws IOException {
        ByteBuffer in = ByteBuffer.wrap(Files.readAllBytes(png));
        byte[] prefix = (KEY + "\0\0\0\0\0").getBytes(StandardCharsets.ISO_8859_1);
        in.position(8);
        while (in.remaining() >= 12) {
            int length = in.getInt();
            byte[] type = new byte[4];
            in.get(type);
            byte[] body = new byte[length];
            in.get(body);
            in.getInt();
            if ("iTXt".equals(new String(type, StandardCharsets.US_ASCII)) && body.length >= prefix.length
                    && Arrays.equals(Arrays.copyOf(body, prefix.length), prefix)) {
                return new String(body, prefix.length, body.length - prefix.length, StandardCharsets.UTF_8);
            }
        }
        return null;
    }

    /** Expands, as a click on its arrow would, the first item of every tree in the shell whose text starts so (for the pictures). */
    static void expandTreesStartingWith(Composite parent, String prefix) {
        for (Control child : parent.getChildren()) {
            if (child instanceof Tree tree && tree.getItemCount() > 0 && tree.getItem(0).getText().startsWith(prefix)) {
                Event expand = new Event();
                expand.item = tree.getItem(0);
                tree.notifyListeners(SWT.Expand, expand);
                tree.getItem(0).setExpanded(true);
            } else if (child instanceof Composite composite) {
                expandTreesStartingWith(composite, prefix);
            }
        }
        processEvents();
    }

    /** The labels of the tree's expanded items, indented by depth, one a line. */
    static String labels(Tree tree) {
        StringBuilder out = new StringBuilder();
        for (TreeItem item : tree.getItems()) {
            labels(item, 0, out);
        }
        return out.toString();
    }

    private static void labels(TreeItem item, int depth, StringBuilder out) {
        out.append("  ".repeat(depth)).append(item.getText()).append('\n');
        if (item.getExpanded()) {
            for (TreeItem child : item.getItems()) {
                labels(child, depth + 1, out);
            }
        }
    }
}
