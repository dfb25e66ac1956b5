/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.zip.CRC32;

import org.rsaml.codegen.CompiledInvariantsWriter;
import org.rsaml.codegen.RsamlCodegen;
import org.rsaml.validation.Rule;

/**
 * The rule catalogue as a Java class of org.rsaml.validation ({@code internal.CompiledCatalog} in its {@code src-gen/}), so that
 * a run takes the rules without parsing the properties file: the rules {@code RuleCatalog.parse} reads from the catalogue, and
 * the length and CRC-32 of the file they were read from, which {@code RuleCatalog.load} compares with the file it finds before
 * it takes them (a catalogue edited since is parsed). The catalogue stays the rules' one definition.
 */
final class CatalogueClass {

    /** The generated class, relative to the repository root. */
    static final String PATH = "bundles/org.rsaml.validation/src-gen/org/rsaml/validation/internal/CompiledCatalog.java";

    private CatalogueClass() {
    }

    /** The source of the class for the catalogue file {@code catalogue}; throws when the catalogue is incomplete. */
    static String source(byte[] catalogue) throws IOException {
        List<Rule> rules = RulesDocument.read(new InputStreamReader(new ByteArrayInputStream(catalogue), StandardCharsets.UTF_8));
        CRC32 crc = new CRC32();
        crc.update(catalogue);
        StringBuilder s = new StringBuilder();
        s.append("/*\n * Copyright (c) 2026 RsaML contributors.\n * SPDX-License-Identifier: EPL-2.0\n */\n");
        s.append("package org.rsaml.validation.internal;\n\n");
        s.append("import java.util.List;\n\n");
        s.append("import org.rsaml.validation.Rule;\n");
        s.append("import org.rsaml.validation.Severity;\n\n");
        s.append("/**\n");
        s.append(" * The rule catalogue (rules/rules.properties of this bundle) as Java, written by releng/org.rsaml.docgen (CatalogueClass)\n");
        s.append(" * from the file: do not edit; regenerate with\n");
        s.append(" * ").append(RsamlCodegen.REGENERATE).append("\n");
        s.append(" * {@link RuleCatalog} takes these rules while the catalogue is the file they were read from (its length and CRC-32).\n");
        s.append(" */\n");
        s.append("final class CompiledCatalog implements CompiledRules {\n\n");
        s.append("    @Override\n    public int length() {\n        return ").append(catalogue.length).append(";\n    }\n\n");
        s.append("    @Override\n    public long crc() {\n        return 0x").append(Long.toHexString(crc.getValue())).append("L;\n    }\n\n");
        s.append("    @Override\n    public List<Rule> rules() {\n");
        s.append("        return List.of(");
        for (int i = 0; i < rules.size(); i++) {
            Rule r = rules.get(i);
            s.append(i == 0 ? "\n" : ",\n");
            s.append("            new Rule(").append(literal(r.id())).append(", ").append(literal(r.name())).append(", Severity.")
                    .append(r.severity().name()).append(",\n");
            s.append("                    ").append(literal(r.source())).append(", ").append(literal(r.context())).append(",\n");
            s.append("                    ").append(literal(r.description())).append(",\n");
            s.append("                    ").append(literal(r.scope())).append(",\n");
            s.append("                    ").append(literal(r.message())).append(",\n");
            s.append("                    ").append(literal(r.remediation())).append(",\n");
            s.append("                    ").append(list(r.constraints())).append(", ").append(list(r.verdicts())).append(", ")
                    .append(r.timingPrerequisite()).append(")");
        }
        s.append(");\n    }\n}\n");
        return s.toString();
    }

    private static String literal(String text) {
        return text == null ? "null" : CompiledInvariantsWriter.literal(text);
    }

    private static String list(List<String> names) {
        StringBuilder b = new StringBuilder("List.of(");
        for (int i = 0; i < names.size(); i++) {
            b.append(i == 0 ? "" : ", ").append(literal(names.get(i)));
        }
        return b.append(')').toString();
    }
}
