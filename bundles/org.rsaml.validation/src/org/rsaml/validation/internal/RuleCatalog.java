/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.CRC32;

import org.rsaml.validation.RsamlValidationSetup.RuleDefinitionException;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Severity;

/**
 * Reads the rule catalogue ({@code rules/rules.properties} of this bundle) and checks that every
 * entry is complete: a rule without a severity, a message or a remediation, or whose message names an
 * unknown parameter, stops RsaML at start-up naming the rule. The catalogue binds rules to what
 * implements them (constraint names, verdict names); this class checks that no name is bound twice.
 */
public final class RuleCatalog {

    /** Where the catalogue is, in this bundle. */
    public static final String RESOURCE = "/rules/rules.properties";

    /** The file in the source tree, for messages and tools that read it from a clone. */
    public static final String SOURCE_FILE = "bundles/org.rsaml.validation" + RESOURCE;

    /** The catalogue as Java ({@link CompiledRules}), written by the regeneration command. */
    private static final String COMPILED = "org.rsaml.validation.internal.CompiledCatalog";

    /** What {@code source} says of the rule that reports EMF's structural checks. */
    public static final String EMF = "EMF";

    private static final Pattern KEY = Pattern.compile("(RSA-\\d\\d)\\.(\\w+)");
    private static final Pattern PARAMETER = Pattern.compile("\\{(\\w+)}");
    private static final List<String> REQUIRED = List.of("name", "severity", "source", "context", "description", "scope",
            "remediation");
    private static final Set<String> KNOWN = Set.of("name", "severity", "source", "constraints", "verdicts",
            "timingPrerequisite", "context", "description", "scope", "message", "remediation");

    private RuleCatalog() {
    }

    /**
     * The rules of the catalogue in id order; throws {@link RuleDefinitionException} when it is incomplete. While the
     * catalogue is the file {@code CompiledCatalog} was generated from (same length and CRC-32), its rules are taken
     * from that class ({@link CompiledRules}), which the regeneration command wrote with {@link #parse} (refusing an incomplete catalogue),
     * without parsing the file in every process; their messages' parameters are checked against this build's
     * {@link MessageParameters} either way.
     */
    public static List<Rule> load() {
        try (InputStream in = RuleCatalog.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new RuleDefinitionException(List.of("the rule catalogue " + RESOURCE + " is missing from org.rsaml.validation"));
            }
            byte[] catalogue = in.readAllBytes();
            List<String> problems = new ArrayList<>();
            List<Rule> rules = compiled(catalogue);
            if (rules != null) {
                for (Rule rule : rules) {
                    unknownParameters(rule.id(), rule.message(), problems);
                }
            } else {
                rules = parse(new InputStreamReader(new ByteArrayInputStream(catalogue), StandardCharsets.UTF_8), problems);
            }
            if (!problems.isEmpty()) {
                throw new RuleDefinitionException(problems);
            }
            structure(rules);
            return rules;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Parses a catalogue, adding one line per incomplete or unknown entry to {@code problems}. */
    public static List<Rule> parse(Reader reader, List<String> problems) throws IOException {
        Properties properties = new Properties();
        properties.load(reader);
        TreeSet<String> ids = new TreeSet<>();
        for (String key : properties.stringPropertyNames()) {
            Matcher m = KEY.matcher(key);
            if (!m.matches() || !KNOWN.contains(m.group(2))) {
                problems.add("rule catalogue: unknown key " + key);
            } else {
                ids.add(m.group(1));
            }
        }
        List<Rule> rules = new ArrayList<>();
        Map<String, String> ruleOfConstraint = new HashMap<>();
        Map<String, String> ruleOfVerdict = new HashMap<>();
        for (String id : ids) {
            List<String> missing = new ArrayList<>();
            for (String key : REQUIRED) {
                if (blank(properties.getProperty(id + "." + key))) {
                    missing.add(key);
                }
            }
            String source = properties.getProperty(id + ".source", "");
            String message = properties.getProperty(id + ".message");
            // EMF's structural findings bring their own messages; every other rule needs one.
            if (!EMF.equals(source.strip()) && blank(message)) {
                missing.add("message");
            }
            if (!missing.isEmpty()) {
                problems.add(id + " has no " + String.join(", no ", missing) + " in the rule catalogue");
                continue;
            }
            Severity severity;
            try {
                severity = Severity.valueOf(properties.getProperty(id + ".severity").strip().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                problems.add(id + " has an unknown severity '" + properties.getProperty(id + ".severity").strip()
                        + "' (error, warning or info)");
                continue;
            }
            unknownParameters(id, message, problems);
            List<String> constraints = names(properties, id, "constraints", ruleOfConstraint, "an invariant implements one rule",
                    problems);
            List<String> verdicts = names(properties, id, "verdicts", ruleOfVerdict, "a verdict is reported as one rule",
                    problems);
            if (!verdicts.isEmpty() && !Rule.TIMING_ANALYSIS.equals(source.strip())) {
                problems.add(id + " names verdicts of the timing analysis but its source is '" + source.strip() + "', not '"
                        + Rule.TIMING_ANALYSIS + "'");
            }
            String prerequisite = properties.getProperty(id + ".timingPrerequisite", "false").strip();
            if (!prerequisite.equals("true") && !prerequisite.equals("false")) {
                problems.add(id + ".timingPrerequisite is '" + prerequisite + "' in the rule catalogue; true or false");
            }
            rules.add(new Rule(id, get(properties, id, "name"), severity, get(properties, id, "source"),
                    get(properties, id, "context"), get(properties, id, "description"), get(properties, id, "scope"),
                    message == null ? null : message.strip(), get(properties, id, "remediation"), constraints, verdicts,
                    prerequisite.equals("true")));
        }
        return rules;
    }

    /**
     * The rules of {@code CompiledCatalog} when {@code catalogue} is the file it was generated from, else {@code null}: the
     * catalogue was edited since, or the class is absent (the generated code being made again).
     */
    private static List<Rule> compiled(byte[] catalogue) {
        CompiledRules compiled;
        try {
            compiled = (CompiledRules) Class.forName(COMPILED, true, RuleCatalog.class.getClassLoader()).getDeclaredConstructor()
                    .newInstance();
        } catch (ClassNotFoundException e) {
            return null;
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(COMPILED + " cannot be made: " + e, e);
        }
        if (catalogue.length != compiled.length()) {
            return null;
        }
        CRC32 crc = new CRC32();
        crc.update(catalogue);
        return crc.getValue() == compiled.crc() ? compiled.rules() : null;
    }

    /** Adds a line to {@code problems} for each parameter {@code message} names that {@link MessageParameters} does not know. */
    private static void unknownParameters(String id, String message, List<String> problems) {
        if (message != null) {
            Matcher p = PARAMETER.matcher(message);
            while (p.find()) {
                if (!MessageParameters.names().contains(p.group(1))) {
                    problems.add(id + "'s message names an unknown parameter {" + p.group(1) + "}; known: "
                            + String.join(", ", new TreeSet<>(MessageParameters.names())));
                }
            }
        }
    }

    /** The one rule of source {@code EMF}, which reports EMF's structural checks and unreadable models. */
    public static Rule structure(Collection<Rule> rules) {
        List<Rule> emf = rules.stream().filter(r -> EMF.equals(r.source())).toList();
        if (emf.size() != 1) {
            throw new RuleDefinitionException(List.of("the rule catalogue " + SOURCE_FILE + " has " + emf.size()
                    + " rules of source " + EMF + "; exactly one reports EMF's structural checks"));
        }
        return emf.get(0);
    }

    /** The blank-separated names under {@code id.key}, each bound to one rule only. */
    private static List<String> names(Properties properties, String id, String key, Map<String, String> ruleOfName, String why,
            List<String> problems) {
        String listed = properties.getProperty(id + "." + key, "").strip();
        List<String> names = listed.isEmpty() ? List.of() : List.of(listed.split("\\s+"));
        for (String name : names) {
            String other = ruleOfName.putIfAbsent(name, id);
            if (other != null) {
                problems.add(id + " and " + other + " both name " + name + " under " + key + " in the rule catalogue; " + why);
            }
        }
        return names;
    }

    private static String get(Properties properties, String id, String key) {
        return properties.getProperty(id + "." + key).strip();
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }
}
