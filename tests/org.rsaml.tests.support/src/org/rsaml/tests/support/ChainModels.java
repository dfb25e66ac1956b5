/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.tests.support;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Legal models whose depth grows with their size, as files: one timed module {@code t} feeding a chain of {@code n}
 * modules {@code m0 .. m(n-1)} that react to data, all in one layer (validation finds nothing in them); closed into a
 * ring, {@code m(n-1)} feeds {@code m0} too.
 */
public final class ChainModels {

    private ChainModels() {
    }

    /** Writes the chain (or ring) of {@code n} reacting modules to {@code file} and returns it. */
    public static Path write(Path file, int n, boolean ring) throws IOException {
        String port = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            out.write("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                    + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                    + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"chain\" declaredLayers=\"1\">\n"
                    + "  <layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n"
                    + "    <modules name=\"t\" timeUnit=\"ms\" type=\"realTime\" period=\"100.0\" delay=\"100.0\" execDuration=\"1.0\""
                    + " execType=\"periodic\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
            for (int i = 0; i < n; i++) {
                out.write("    <modules name=\"m" + i + "\" timeUnit=\"ms\" execDuration=\"0.001\"><ports xsi:type=\"rsaml:EntryPort\""
                        + " name=\"i\" dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
            }
            out.write("  </layers>\n");
            out.write(connection(port.formatted("t", "o"), port.formatted("m0", "i")));
            for (int i = 0; i < (ring ? n : n - 1); i++) {
                out.write(connection(port.formatted("m" + i, "o"), port.formatted("m" + (i + 1) % n, "i")));
            }
            out.write("</rsaml:Architecture>\n");
        }
        return file;
    }

    private static String connection(String source, String target) {
        return "  <connections source=\"" + source + "\" target=\"" + target + "\"/>\n";
    }
}
