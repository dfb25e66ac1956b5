/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.rsaml.model.support.RsamlText;

/** Model text put into the XML RsaML writes (SVG, package manifests) never breaks or forges the document. */
class XmlTextTest {

    @Test
    void markupIsEscapedForContentAndBothQuotes() {
        assertEquals("a &lt;b&gt; &amp; &quot;c&quot; &#39;d&#39;", RsamlText.xml("a <b> & \"c\" 'd'"), "markup characters");
        assertEquals("", RsamlText.xml(null), "a missing text is empty");
    }

    @Test
    void whatXmlCannotCarryBecomesASpaceAndEverythingElseIsKept() {
        assertEquals("a b\tc\nd\re f g", RsamlText.xml("a\u0001b\tc\nd\re\uFFFEf\uD800g"), "control characters and a lone surrogate");
        assertEquals("robot \uD83E\uDD16 é", RsamlText.xml("robot \uD83E\uDD16 é"), "a character outside the BMP and accents are kept");
    }

    @Test
    void anyTextParsesBackAsItselfInAnAttributeAndInContent() throws Exception {
        String hostile = "</title><script>alert('x')</script>\"/><x a='1'> &lt; ]]>";
        String xml = "<r a=\"" + RsamlText.xml(hostile) + "\" b='" + RsamlText.xml(hostile) + "'>" + RsamlText.xml(hostile) + "</r>";
        var root = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8))).getDocumentElement();
        assertEquals(hostile, root.getAttribute("a"), "in a double-quoted attribute");
        assertEquals(hostile, root.getAttribute("b"), "in a single-quoted attribute");
        assertEquals(hostile, root.getTextContent(), "as content");
        assertEquals(0, root.getChildNodes().getLength() - 1, "no element was forged");
    }
}
