/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Font;
import java.awt.font.FontRenderContext;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.rsaml.diagram.internal.TextMetrics;

/** The shipped widths are DejaVu Sans's: checked against the font file, as AWT measures it. */
class TextMetricsTest {

    private static final Path FONTS = Path.of("/usr/share/fonts/truetype/dejavu");

    @Test
    void shippedWidthsAreThoseOfTheInstalledDejaVuSans() throws Exception {
        System.setProperty("java.awt.headless", "true");
        assertTrue(Files.exists(FONTS.resolve("DejaVuSans.ttf")),
                "the metrics check needs DejaVu Sans: install the Debian package fonts-dejavu-core");
        FontRenderContext context = new FontRenderContext(null, false, true);
        Font regular = Font.createFont(Font.TRUETYPE_FONT, FONTS.resolve("DejaVuSans.ttf").toFile()).deriveFont(1000f);
        Font bold = Font.createFont(Font.TRUETYPE_FONT, FONTS.resolve("DejaVuSans-Bold.ttf").toFile()).deriveFont(1000f);
        assertTrue(TextMetrics.codePoints().size() > 300, "the shipped widths cover more than Latin-1: labels in other scripts are measured");
        for (int cp : TextMetrics.codePoints()) {
            if (Character.getType(cp) == Character.FORMAT) {
                // The soft hyphen (U+00AD): Java 17 measures its glyph, Java 24 and later treat it as invisible.
                continue;
            }
            String s = new String(Character.toChars(cp));
            int[] shipped = TextMetrics.advance(cp);
            assertEquals(Math.round(regular.getStringBounds(s, context).getWidth()), shipped[0], 0, "regular U+" + Integer.toHexString(cp));
            assertEquals(Math.round(bold.getStringBounds(s, context).getWidth()), shipped[1], 0, "bold U+" + Integer.toHexString(cp));
        }
        assertEquals(regular.getStringBounds("resourceChecker", context).getWidth() * 12 / 1000,
                TextMetrics.width("resourceChecker", 12, false), 0.1, "a label's width at 12 pt is the font's, so labels fit their boxes");
    }
}
