/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** Every example's HTML page is self-contained: nothing to fetch, its data readable, its findings listed. */
class HtmlReportTest {

    @ParameterizedTest(name = "{0}")
    @MethodSource("org.rsaml.diagram.tests.Examples#names")
    void selfContainedPageWithFindingsAndElementData(String name) throws Exception {
        for (DiagramView view : DiagramView.values()) {
            LoadedModel model = ModelLoader.load(TestRepository.example(name), "examples/" + name);
            var findings = RsamlModelValidator.validate(model);
            String html = new RsamlDiagrams(view).html(model.architecture(), "examples/" + name, findings);
            assertFalse(Pattern.compile("<(script|link|img|iframe)[^>]*(src|href)=", Pattern.CASE_INSENSITIVE).matcher(html).find(),
                    "no external script, style or image");
            Matcher urls = Pattern.compile("https?://[^\"'\\s)]+").matcher(html);
            while (urls.find()) {
                assertEquals("http://www.w3.org/2000/svg", urls.group(), "the only address is the SVG namespace");
            }
            Matcher data = Pattern.compile("<script type=\"application/json\" id=\"rsaml-data\">(.*?)</script>", Pattern.DOTALL).matcher(html);
            assertTrue(data.find(), "the page carries the model's data inline");
            JsonObject json = JsonParser.parseString(data.group(1)).getAsJsonObject();
            assertEquals(view.id(), json.get("view").getAsString(), "the page's data names the view drawn");
            if (view == DiagramView.ARCHITECTURE || !model.architecture().getMissions().isEmpty()) {
                assertTrue(json.getAsJsonObject("elements").size() > 3, "the page describes the drawn elements");
            }
            int items = html.split("<li class=\"finding ", -1).length - 1;
            assertEquals(findings.size(), items, "every finding listed");
        }
    }
}
