/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;

/**
 * Text widths from the advance widths of DejaVu Sans, shipped with the bundle so that layouts do
 * not depend on the fonts of the machine that draws them (the same model gives the same SVG
 * everywhere). The SVG names DejaVu Sans first; characters outside the table count as a full em,
 * which errs on the wide side.
 */
public final class TextMetrics {

    /** The font family written into the SVG, measured font first. */
    public static final String FONT_FAMILY = "'DejaVu Sans', Verdana, sans-serif";
    public static final double ASCENT = 0.928;
    public static final double DESCENT = 0.236;
    /** Distance between baselines, in ems. */
    public static final double LINE_HEIGHT = 1.3;

    private static final Map<Integer, int[]> WIDTHS = load();

    private TextMetrics() {
    }

    /** The advance width of {@code text} at {@code size} pixels. */
    public static double width(String text, double size, boolean bold) {
        long thousandths = 0;
        for (int i = 0; i < text.length();) {
            int cp = text.codePointAt(i);
            int[] w = WIDTHS.get(cp);
            thousandths += w == null ? 1000 : w[bold ? 1 : 0];
            i += Character.charCount(cp);
        }
        return thousandths * size / 1000.0;
    }

    /** The advance widths, in thousandths of an em, of a code point (regular, bold), or null if unknown. */
    public static int[] advance(int codePoint) {
        int[] w = WIDTHS.get(codePoint);
        return w == null ? null : w.clone();
    }

    /** The code points with known widths. */
    public static java.util.Set<Integer> codePoints() {
        return java.util.Collections.unmodifiableSet(WIDTHS.keySet());
    }

    public static double lineHeight(double size) {
        return size * LINE_HEIGHT;
    }

    private static Map<Integer, int[]> load() {
        Map<Integer, int[]> widths = new HashMap<>();
        try (InputStream in = TextMetrics.class.getResourceAsStream("dejavu-sans.widths")) {
            if (in == null) {
                throw new IllegalStateException("dejavu-sans.widths is missing from org.rsaml.diagram");
            }
            BufferedReader reader = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                if (line.isBlank() || line.startsWith("#")) {
                    continue;
                }
                int eq = line.indexOf('=');
                int comma = line.indexOf(',');
                widths.put(Integer.parseInt(line.substring(0, eq), 16), new int[] {
                        Integer.parseInt(line.substring(eq + 1, comma)), Integer.parseInt(line.substring(comma + 1)) });
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return widths;
    }
}
