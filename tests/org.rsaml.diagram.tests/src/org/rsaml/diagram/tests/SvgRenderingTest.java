/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.rsaml.diagram.DiagramView;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * Every example's SVG, in both views, opened by Chromium as an image of its own: it parses, Chromium
 * logs no invalid SVG (negative sizes, malformed path data, unknown values), it is drawn at its
 * declared size with every element, and it is not blank. Screenshots in target/browser/.
 */
class SvgRenderingTest {

    @Test
    void everyExampleRendersWithoutAnSvgError() throws Exception {
        Path dir = Browser.OUT.resolve("svg");
        Files.createDirectories(dir);
        Map<String, SvgDocument> written = new LinkedHashMap<>();
        for (String name : Examples.names()) {
            for (DiagramView view : DiagramView.values()) {
                String svg = Examples.draw(name, view).svg();
                Path file = dir.resolve(name.replace(".rsaml", "") + "-" + view.id() + ".svg");
                Files.writeString(file, svg);
                written.put(file.toString(), new SvgDocument(svg));
            }
        }
        JsonObject seen = Browser.run("svg-rendering", List.of("--svg"), new ArrayList<>(written.keySet()));
        assertEquals(written.size(), seen.getAsJsonArray("images").size(), "the browser rendered every written SVG");
        for (JsonElement e : seen.getAsJsonArray("images")) {
            JsonObject image = e.getAsJsonObject();
            String file = image.get("file").getAsString();
            SvgDocument svg = written.get(file);
            assertEquals("[]", image.getAsJsonArray("errors").toString(), file + ": Chromium reports no SVG error");
            assertFalse(image.get("parseError").getAsBoolean(), file + " parses");
            assertEquals("svg", image.get("root").getAsString(), file);
            String[] viewBox = svg.document.getDocumentElement().getAttribute("viewBox").split(" ");
            assertEquals(Double.parseDouble(viewBox[2]), image.get("width").getAsDouble(), 1.0, file + ": drawn across its width");
            assertEquals(Double.parseDouble(viewBox[3]), image.get("height").getAsDouble(), 1.0, file + ": drawn down its height");
            assertEquals(svg.shapes.size() + svg.links.stream().filter(l -> l.qname() != null).count(), image.get("elements").getAsInt(),
                    file + ": every element is in the rendered document");
            if (image.get("elements").getAsInt() > 1) {
                Browser.assertNotBlank(Path.of(image.get("screenshot").getAsString()));
            }
        }
    }
}
