/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.RsamlValidationSetup.RuleDefinitionException;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Severity;

/**
 * Reads the rule catalogue ({@code model/rules.properties} beside {@code rsaml.ecore}) and checks
 * that every entry is complete: a rule without a severity, a message or a remediation, or whose
 * message names an unknown parameter, stops RsaML at start-up naming the rule.
 */
public final class RuleCatalog {

    /** Where the catalogue is, in the model bundle. */
    public static final String RESOURCE = "/model/rules.properties";

    private static final Pattern KEY = Pattern.compile("(RSA-\\d\\d)\\.(\\w+)");
    private static final Pattern PARAMETER = Pattern.compile("\\{(\\w+)}");
    private static final List<String> REQUIRED = List.of("name", "severity", "source", "context", "description", "scope",
            "remediation");
    private static final Set<String> KNOWN = Set.of("name", "severity", "source", "constraints", "context", "description",
            "scope", "message", "remediation");

    private RuleCatalog() {
    }

    /** The rules of the catalogue in id order; throws {@link RuleDefinitionException} when it is incomplete. */
    public static List<Rule> load() {
        try (InputStream in = RsamlPackage.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new RuleDefinitionException(List.of("the rule catalogue " + RESOURCE + " is missing from org.rsaml.model"));
            }
            List<String> problems = new ArrayList<>();
            List<Rule> rules = parse(new InputStreamReader(in, StandardCharsets.UTF_8), problems);
            if (!problems.isEmpty()) {
                throw new RuleDefinitionException(problems);
            }
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
            if (!"EMF".equals(source.strip()) && blank(message)) {
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
            if (message != null) {
                Matcher p = PARAMETER.matcher(message);
                while (p.find()) {
                    if (!MessageParameters.names().contains(p.group(1))) {
                        problems.add(id + "'s message names an unknown parameter {" + p.group(1) + "}; known: "
                                + String.join(", ", new TreeSet<>(MessageParameters.names())));
                    }
                }
            }
            String listed = properties.getProperty(id + ".constraints", "").strip();
            List<String> constraints = listed.isEmpty() ? List.of() : List.of(listed.split("\\s+"));
            for (String constraint : constraints) {
                String other = ruleOfConstraint.putIfAbsent(constraint, id);
                if (other != null) {
                    problems.add(id + " and " + other + " both name the constraint " + constraint + " in the rule catalogue; "
                            + "an invariant implements one rule");
                }
            }
            rules.add(new Rule(id, get(properties, id, "name"), severity, get(properties, id, "source"),
                    get(properties, id, "context"), get(properties, id, "description"), get(properties, id, "scope"),
                    message == null ? null : message.strip(), get(properties, id, "remediation"), constraints));
        }
        return rules;
    }

    private static String get(Properties properties, String id, String key) {
        return properties.getProperty(id + "." + key).strip();
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }
}
