/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.internal;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;

import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;

import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.ReportOptions;
import org.rsaml.report.Text;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.Rule;

/**
 * JUnit XML as the test reporters of Jenkins, GitLab and GitHub Actions read it: a test suite per
 * model file; in it a passing test per rule the file satisfies, a failing test per finding at or
 * above the failure threshold (named after rule and element), and an erroring test when the file
 * could not be read. Findings below the threshold leave their test passing, with the finding as
 * its output, so the report agrees with the exit code. Text from the model is written as
 * {@link Text#line} shows it: XML 1.0 cannot carry most control characters, and CI pages show these
 * names to people.
 */
public final class JUnitReport {

    /** A test: failed by {@code failure} when set; {@code notes} are findings below the threshold. */
    private record Case(String name, Finding failure, List<Finding> notes) {
        boolean failed() {
            return failure != null;
        }
    }

    private JUnitReport() {
    }

    public static void write(Report report, Writer out, ReportOptions options) throws IOException {
        try {
            XMLStreamWriter xml = XMLOutputFactory.newFactory().createXMLStreamWriter(out);
            xml.writeStartDocument("UTF-8", "1.0");
            newline(xml, 0);
            long tests = 0;
            long failures = 0;
            long errors = 0;
            List<List<Case>> suites = new ArrayList<>();
            for (FileResult result : report.results()) {
                List<Case> cases = cases(result, report);
                suites.add(cases);
                tests += result.readable() ? cases.size() : 1;
                failures += cases.stream().filter(Case::failed).count();
                errors += result.readable() ? 0 : 1;
            }
            xml.writeStartElement("testsuites");
            xml.writeAttribute("name", "rsaml");
            xml.writeAttribute("tests", Long.toString(tests));
            xml.writeAttribute("failures", Long.toString(failures));
            xml.writeAttribute("errors", Long.toString(errors));
            for (int i = 0; i < suites.size(); i++) {
                suite(xml, report.results().get(i), suites.get(i));
            }
            newline(xml, 0);
            xml.writeEndElement();
            xml.writeEndDocument();
            xml.flush();
            out.write('\n');
        } catch (XMLStreamException e) {
            throw new IOException("cannot write the JUnit report: " + e.getMessage(), e);
        }
    }

    private static List<Case> cases(FileResult result, Report report) {
        List<Case> cases = new ArrayList<>();
        if (!result.readable()) {
            return cases;
        }
        for (Rule rule : report.rules()) {
            String test = rule.id() + " " + rule.name();
            List<Finding> found = result.findings().stream().filter(f -> f.rule().equals(rule)).toList();
            List<Finding> failing = found.stream().filter(report::fails).toList();
            List<Finding> notes = found.stream().filter(f -> !report.fails(f)).toList();
            if (failing.isEmpty()) {
                cases.add(new Case(test, null, notes));
            }
            for (int i = 0; i < failing.size(); i++) {
                Finding f = failing.get(i);
                cases.add(new Case(test + " (" + f.qualifiedName() + ")", f, i == 0 ? notes : List.of()));
            }
        }
        return cases;
    }

    private static void suite(XMLStreamWriter xml, FileResult result, List<Case> cases) throws XMLStreamException {
        newline(xml, 1);
        xml.writeStartElement("testsuite");
        xml.writeAttribute("name", Text.line(result.file()));
        xml.writeAttribute("tests", Integer.toString(result.readable() ? cases.size() : 1));
        xml.writeAttribute("failures", Long.toString(cases.stream().filter(Case::failed).count()));
        xml.writeAttribute("errors", result.readable() ? "0" : "1");
        xml.writeAttribute("skipped", "0");
        xml.writeAttribute("time", String.format(java.util.Locale.ROOT, "%.3f", result.seconds()));
        if (!result.readable()) {
            newline(xml, 2);
            xml.writeStartElement("testcase");
            xml.writeAttribute("classname", Text.line(result.file()));
            xml.writeAttribute("name", "load model");
            xml.writeStartElement("error");
            xml.writeAttribute("type", "input");
            List<ModelLoadException.Problem> problems = result.error().problems();
            xml.writeAttribute("message", Text.line(result.error().getMessage())
                    + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more errors, all listed in the text below)" : ""));
            xml.writeCharacters(String.join("\n", Text.lines(result.error())));
            xml.writeEndElement();
            xml.writeEndElement();
        }
        for (Case c : cases) {
            newline(xml, 2);
            xml.writeStartElement("testcase");
            xml.writeAttribute("classname", Text.line(result.file()));
            xml.writeAttribute("name", Text.line(c.name()));
            if (c.failed()) {
                xml.writeStartElement("failure");
                xml.writeAttribute("type", c.failure().ruleId());
                xml.writeAttribute("message", Text.line(c.failure().message()));
                xml.writeCharacters(Text.line(c.failure().toString()));
                xml.writeEndElement();
            }
            if (!c.notes().isEmpty()) {
                xml.writeStartElement("system-out");
                xml.writeCharacters(String.join("\n", c.notes().stream().map(f -> Text.line(f.toString())).toList()));
                xml.writeEndElement();
            }
            xml.writeEndElement();
        }
        newline(xml, 1);
        xml.writeEndElement();
    }

    private static void newline(XMLStreamWriter xml, int depth) throws XMLStreamException {
        xml.writeCharacters("\n" + "  ".repeat(depth));
    }
}
