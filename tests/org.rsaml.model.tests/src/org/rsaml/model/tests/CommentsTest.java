/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.tests.support.TestRepository;

/**
 * Saving a model (the tree editor's Save, any EMF client's) keeps the file's XML comments where they
 * stood: before the element they precede, inside an element after its last child, after the root.
 */
class CommentsTest {

    private static final Pattern COMMENT = Pattern.compile("<!--(.*?)-->", Pattern.DOTALL);

    @TempDir
    Path dir;

    private RsamlResource load(Path file) throws Exception {
        RsamlResource resource = (RsamlResource) new ResourceSetImpl().getResource(URI.createFileURI(file.toString()), true);
        assertTrue(resource.getErrors().isEmpty(), () -> file + " must load: " + resource.getErrors());
        return resource;
    }

    private static List<String> comments(String text) {
        List<String> out = new ArrayList<>();
        Matcher m = COMMENT.matcher(text);
        while (m.find()) {
            out.add(m.group(1));
        }
        return out;
    }

    /** The line of {@code text} holding {@code needle}, trimmed; fails when there is none. */
    private static int lineOf(List<String> lines, String needle) {
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains(needle)) {
                return i;
            }
        }
        throw new AssertionError("no line holds " + needle + " in\n" + String.join("\n", lines));
    }

    @Test
    void anEditedExampleKeepsEveryCommentBeforeItsElement() throws Exception {
        Path file = dir.resolve("exp2-defects.rsaml");
        Files.copy(TestRepository.example("exp2-defects.rsaml"), file);
        String original = Files.readString(file);
        RsamlResource resource = load(file);
        assertEquals(comments(original).size(), resource.keptCommentCount(), "every comment of exp2 must be kept on load");

        Architecture architecture = (Architecture) resource.getContents().get(0);
        Layer control = architecture.getLayers().stream().filter(l -> l.getName().equals("control")).findFirst().orElseThrow();
        Module checker = control.getModules().stream().filter(m -> m.getName().equals("resourceChecker")).findFirst().orElseThrow();
        checker.setExecDuration(1.5);
        resource.save(null);

        String saved = Files.readString(file);
        assertEquals(comments(original), comments(saved), "the saved file must hold exp2's comments, in their order");
        assertTrue(saved.contains("execDuration=\"1.5\""), "the edit must be saved");
        List<String> lines = saved.lines().toList();
        int defect4 = lineOf(lines, "<!-- Defect 4 (RSA-08)");
        assertTrue(lines.get(defect4 + 1).trim().startsWith("<modules name=\"resourceChecker\""),
                () -> "the Defect 4 comment must stay right before resourceChecker's start tag, not before: " + lines.get(defect4 + 1));
        assertEquals(lines.get(defect4 + 1).indexOf('<'), lines.get(defect4).indexOf('<'),
                "the comment must be indented as the element it precedes");
        int end = lineOf(lines, "</rsaml:Architecture>");
        int expect = lineOf(lines, "<!-- expect: RSA-01");
        assertTrue(expect > end, "the expect lines must stay after the root element");
        int header = lineOf(lines, "RsaML paper, experiment 2");
        assertTrue(header < lineOf(lines, "<rsaml:Architecture"), "the header comment must stay before the root element");

        RsamlResource reloaded = load(file);
        assertEquals(resource.keptCommentCount(), reloaded.keptCommentCount(), "saving again must not lose or add comments");
    }

    @Test
    void commentsAfterTheLastChildAndInAnEmptiedElementStayInside() throws Exception {
        Path file = dir.resolve("commented.rsaml");
        Files.writeString(file, XmiFiles.model("""
                  <!-- the only layer -->
                  <layers name="l0" level="0">
                    <modules name="m0"/>
                    <!-- more modules come here -->
                  </layers>
                """).replace("declaredLayers=\"1\">", "declaredLayers=\"1\">\n  <!-- leading -->")
                + "<!-- after the root -->\n");
        RsamlResource resource = load(file);
        assertEquals(4, resource.keptCommentCount(), "four comments must be kept");

        Layer layer = ((Architecture) resource.getContents().get(0)).getLayers().get(0);
        layer.getModules().clear();
        resource.save(null);
        List<String> lines = Files.readString(file).lines().toList();
        int layerStart = lineOf(lines, "<layers name=\"l0\"");
        int trailing = lineOf(lines, "<!-- more modules come here -->");
        int layerEnd = lineOf(lines, "</layers>");
        assertTrue(layerStart < trailing && trailing < layerEnd,
                () -> "the comment after the last module must stay inside the emptied layer:\n" + String.join("\n", lines));
        assertTrue(lineOf(lines, "<!-- leading -->") < lineOf(lines, "<!-- the only layer -->"),
                "both comments before the layer must stay, in their order");
        assertTrue(lineOf(lines, "<!-- after the root -->") > lineOf(lines, "</rsaml:Architecture>"),
                "the comment after the root must stay after it");

        Module added = RsamlFactory.eINSTANCE.createModule();
        added.setName("m1");
        layer.getModules().add(added);
        resource.save(null);
        List<String> again = Files.readString(file).lines().toList();
        assertTrue(lineOf(again, "<modules name=\"m1\"") < lineOf(again, "<!-- more modules come here -->"),
                "a module added at the end comes before the comment that closed the layer");
    }

    @Test
    void aDeletedElementTakesItsCommentAlong() throws Exception {
        Path file = dir.resolve("deleted.rsaml");
        Files.writeString(file, XmiFiles.model("""
                  <layers name="l0" level="0">
                    <!-- m0 is obsolete -->
                    <modules name="m0"/>
                    <modules name="m1"/>
                  </layers>
                """));
        RsamlResource resource = load(file);
        ((Architecture) resource.getContents().get(0)).getLayers().get(0).getModules().remove(0);
        resource.save(null);
        String saved = Files.readString(file);
        assertFalse(saved.contains("m0 is obsolete"), () -> "the comment about the deleted module must go with it:\n" + saved);
        assertTrue(saved.contains("<modules name=\"m1\"/>"), "the other module must stay");
    }

    @Test
    void locationsFollowTheSavedFile() throws Exception {
        Path file = dir.resolve("moved.rsaml");
        Files.writeString(file, XmiFiles.model("""
                  <layers name="l0" level="0">
                    <modules name="m0"/>
                  </layers>
                """));
        RsamlResource resource = load(file);
        Layer layer = ((Architecture) resource.getContents().get(0)).getLayers().get(0);
        Module m0 = layer.getModules().get(0);
        int before = resource.locate(m0).line();
        Module inserted = RsamlFactory.eINSTANCE.createModule();
        inserted.setName("first");
        layer.getModules().add(0, inserted);
        assertEquals(0, resource.locate(inserted).line(), "an element not yet saved has no line");
        resource.save(null);
        resource.refreshLocations();
        assertEquals(before + 1, resource.locate(m0).line(), "m0 moved one line down in the saved file");
        assertEquals(before, resource.locate(inserted).line(), "the saved module has the line it was written on");
    }
}
