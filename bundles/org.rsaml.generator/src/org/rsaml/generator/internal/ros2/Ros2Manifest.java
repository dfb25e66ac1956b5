/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;

import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;

import org.rsaml.generator.GenerationException;
import org.rsaml.generator.internal.Names;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * What the architect adds to a generated package's manifest: {@code package.user.xml}, theirs,
 * holds the version, maintainers, licences, URLs, authors and further dependencies that the
 * regenerated {@code package.xml} takes over (REP 149 order). Also reads which packages a
 * {@code .msg} file's fields come from.
 */
public final class Ros2Manifest {

    /** The architect's file beside package.xml. */
    public static final String FILE = "package.user.xml";

    private static final String ROOT = "package_user";
    private static final List<String> DEPENDENCY_TAGS = List.of("buildtool_depend", "buildtool_export_depend", "build_depend",
            "build_export_depend", "depend", "exec_depend", "test_depend", "doc_depend", "conflict", "replace");
    private static final Set<String> TAGS = Set.of("version", "maintainer", "license", "url", "author", "buildtool_depend",
            "buildtool_export_depend", "build_depend", "build_export_depend", "depend", "exec_depend", "test_depend",
            "doc_depend", "conflict", "replace");
    private static final Pattern VERSION = Pattern.compile("(0|[1-9][0-9]*)(\\.(0|[1-9][0-9]*)){2}");
    private static final Pattern PACKAGE = Pattern.compile("[a-z][a-z0-9_]*");

    /** An element as the architect wrote it: its tag, its text, and itself as XML. */
    public record Element(String tag, String text, String xml) {
    }

    private final List<Element> elements;

    private Ros2Manifest(List<Element> elements) {
        this.elements = elements;
    }

    /** The file the architect starts with: today's defaults, to edit. */
    public static String initialText(String pkg) {
        return """
                <?xml version="1.0"?>
                <!-- Yours: created once by RsaML, never overwritten. The regenerated package.xml of
                     %s takes its version, maintainers, licences, URLs, authors and further
                     dependencies from here (REP 149 elements, in any order). -->
                <package_user>
                  <version>0.1.0</version>
                  <maintainer email="maintainer@example.com">Maintainer</maintainer>
                  <license>TODO</license>
                  <!-- <url type="repository">https://example.com/robot.git</url> -->
                  <!-- <author email="author@example.com">Author</author> -->
                  <!-- <depend>tf2_ros</depend> -->
                </package_user>
                """.formatted(pkg);
    }

    /** The defaults, when the architect's file does not exist yet. */
    public static Ros2Manifest initial(String pkg) {
        try {
            return parse("package.user.xml", initialText(pkg));
        } catch (GenerationException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Reads the architect's file.
     *
     * @param path the file's path in the output, for messages
     * @throws GenerationException naming the file and line: not XML, another root, an element
     *                             package.xml does not take from here, a bad version or maintainer
     */
    public static Ros2Manifest parse(String path, String text) throws GenerationException {
        List<Element> elements = new ArrayList<>();
        DefaultHandler handler = new DefaultHandler() {
            Locator locator;
            int depth;
            String tag;
            StringBuilder xml;
            StringBuilder content;

            @Override
            public void setDocumentLocator(Locator locator) {
                this.locator = locator;
            }

            private SAXParseException error(String message) {
                return new SAXParseException(message, locator);
            }

            @Override
            public void startElement(String uri, String localName, String qName, Attributes attributes) throws SAXException {
                depth++;
                if (depth == 1) {
                    if (!qName.equals(ROOT)) {
                        throw error("the root element must be <" + ROOT + ">, not <" + qName + ">");
                    }
                    return;
                }
                if (depth > 2) {
                    throw error("<" + qName + "> inside <" + tag + ">: package.xml takes these elements with text only");
                }
                if (!TAGS.contains(qName)) {
                    throw error("<" + qName + "> is not taken into package.xml from here; use version, maintainer, license, url, author or a dependency ("
                            + String.join(", ", DEPENDENCY_TAGS) + ")");
                }
                tag = qName;
                content = new StringBuilder();
                xml = new StringBuilder("<").append(qName);
                for (int i = 0; i < attributes.getLength(); i++) {
                    xml.append(' ').append(attributes.getQName(i)).append("=\"").append(Names.xml(attributes.getValue(i))).append('"');
                }
                xml.append('>');
                if (qName.equals("maintainer") && attributes.getValue("email") == null) {
                    throw error("<maintainer> needs an email attribute (REP 149)");
                }
            }

            @Override
            public void characters(char[] ch, int start, int length) throws SAXException {
                if (depth == 2) {
                    content.append(ch, start, length);
                } else if (depth == 1 && !new String(ch, start, length).isBlank()) {
                    throw error("text outside an element in <" + ROOT + ">");
                }
            }

            @Override
            public void endElement(String uri, String localName, String qName) throws SAXException {
                if (depth == 2) {
                    String text = content.toString().trim();
                    if (text.isEmpty()) {
                        throw error("<" + tag + "> is empty");
                    }
                    if (tag.equals("version") && !VERSION.matcher(text).matches()) {
                        throw error("version '" + text + "' is not MAJOR.MINOR.PATCH (REP 149), e.g. 0.1.0");
                    }
                    if (DEPENDENCY_TAGS.contains(tag) && !PACKAGE.matcher(text).matches()) {
                        throw error("'" + text + "' is not a ROS package name (lower case letters, digits, _)");
                    }
                    elements.add(new Element(tag, text, xml + Names.xml(text) + "</" + tag + ">"));
                }
                depth--;
            }
        };
        try {
            SAXParserFactory factory = SAXParserFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.newSAXParser().parse(new InputSource(new StringReader(text)), handler);
        } catch (SAXParseException e) {
            throw new GenerationException(path, Math.max(e.getLineNumber(), 0), Math.max(e.getColumnNumber(), 0), e.getMessage(), null);
        } catch (SAXException | IOException | ParserConfigurationException e) {
            throw new GenerationException(path, "cannot be read: " + e.getMessage(), e);
        }
        long versions = elements.stream().filter(e -> e.tag().equals("version")).count();
        if (versions > 1) {
            throw new GenerationException(path, "has " + versions + " <version> elements; package.xml has one");
        }
        for (String required : List.of("maintainer", "license")) {
            if (elements.stream().noneMatch(e -> e.tag().equals(required))) {
                throw new GenerationException(path, "has no <" + required + ">; package.xml needs at least one (REP 149)");
            }
        }
        return new Ros2Manifest(elements);
    }

    /**
     * Whether the architect's file says something of their own: elements other than those RsaML
     * created it with (comments aside); a file that is not a valid {@code package.user.xml} does too.
     */
    public static boolean hasAdditions(String path, String text) {
        try {
            return !parse(path, text).elements.equals(initial("").elements);
        } catch (GenerationException e) {
            return true;
        }
    }

    public String version() {
        return elements.stream().filter(e -> e.tag().equals("version")).map(Element::text).findFirst().orElse("0.1.0");
    }

    /** The XML of the elements with this tag, in the architect's order. */
    public List<String> xml(String tag) {
        return elements.stream().filter(e -> e.tag().equals(tag)).map(Element::xml).toList();
    }

    /**
     * The architect's dependency elements, in REP 149's tag order, leaving out those the generated
     * manifest already declares for the same package (catkin_pkg refuses duplicates).
     *
     * @param generated tag + " " + package of the generated dependencies
     */
    public List<String> dependencies(Set<String> generated) {
        List<String> out = new ArrayList<>();
        Set<String> seen = new LinkedHashSet<>(generated);
        for (String g : generated) {
            // <depend> stands for the build, build export and exec dependencies.
            if (g.startsWith("depend ")) {
                String pkg = g.substring("depend ".length());
                seen.addAll(List.of("build_depend " + pkg, "build_export_depend " + pkg, "exec_depend " + pkg));
            }
        }
        for (String tag : DEPENDENCY_TAGS) {
            for (Element e : elements) {
                if (e.tag().equals(tag) && seen.add(tag + " " + e.text())) {
                    out.add(e.xml());
                }
            }
        }
        return out;
    }

    /** The packages the architect depends on at build time ({@code depend}, {@code build_depend}). */
    public Set<String> buildDependencies() {
        Set<String> out = new TreeSet<>();
        for (Element e : elements) {
            if (e.tag().equals("depend") || e.tag().equals("build_depend")) {
                out.add(e.text());
            }
        }
        return out;
    }

    /**
     * The other packages a {@code .msg} file's fields and constants use ({@code std_msgs/Header},
     * {@code geometry_msgs/msg/Twist[]}), sorted.
     */
    public static Set<String> messageDependencies(String msg, String ownPackage) {
        Set<String> packages = new TreeSet<>();
        for (String line : msg.split("\n")) {
            int hash = line.indexOf('#');
            String field = (hash >= 0 ? line.substring(0, hash) : line).trim();
            if (field.isEmpty() || field.equals("---")) {
                continue;
            }
            String type = field.split("\\s+")[0];
            int slash = type.indexOf('/');
            if (slash > 0) {
                String pkg = type.substring(0, slash);
                if (PACKAGE.matcher(pkg).matches() && !pkg.equals(ownPackage)) {
                    packages.add(pkg);
                }
            }
        }
        return packages;
    }
}
