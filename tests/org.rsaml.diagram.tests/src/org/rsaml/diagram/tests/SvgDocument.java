/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import java.io.StringReader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;

import org.rsaml.diagram.internal.TextMetrics;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/** An SVG diagram read back with the JDK's XML parser: what a tool finds in the file. */
final class SvgDocument {

    static final String SVG_NS = "http://www.w3.org/2000/svg";

    record Box(double x, double y, double width, double height) {
        double right() {
            return x + width;
        }

        double bottom() {
            return y + height;
        }

        /** Interiors intersect by more than {@code tolerance} in both directions. */
        boolean overlaps(Box o, double tolerance) {
            return Math.min(right(), o.right()) - Math.max(x, o.x) > tolerance
                    && Math.min(bottom(), o.bottom()) - Math.max(y, o.y) > tolerance;
        }

        boolean contains(Box o, double tolerance) {
            return o.x >= x - tolerance && o.y >= y - tolerance && o.right() <= right() + tolerance && o.bottom() <= bottom() + tolerance;
        }

        boolean contains(double px, double py, double tolerance) {
            return px >= x - tolerance && px <= right() + tolerance && py >= y - tolerance && py <= bottom() + tolerance;
        }
    }

    record Text(String text, Box box) {
    }

    record Shape(String id, String kind, String qname, String uri, String parent, List<String> classes, Box box,
            List<Text> texts, List<String> badges, Map<String, String> data) {
    }

    record Link(String id, String kind, String qname, String uri, String source, String target, List<String> classes,
            List<double[]> points, List<String> badges, Map<String, String> data) {
    }

    final Document document;
    final Map<String, Shape> shapes = new LinkedHashMap<>();
    final List<Link> links = new ArrayList<>();

    SvgDocument(String svg) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setNamespaceAware(true);
        factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        DocumentBuilder builder = factory.newDocumentBuilder();
        builder.setErrorHandler(null);
        document = builder.parse(new InputSource(new StringReader(svg)));
        NodeList groups = document.getElementsByTagNameNS(SVG_NS, "g");
        for (int i = 0; i < groups.getLength(); i++) {
            Element g = (Element) groups.item(i);
            List<String> classes = Arrays.asList(g.getAttribute("class").split(" "));
            if (!g.hasAttribute("data-kind")) {
                continue;
            }
            if (classes.contains("link")) {
                links.add(new Link(g.getAttribute("id"), g.getAttribute("data-kind"), attr(g, "data-qname"), attr(g, "data-uri"), attr(g, "data-source"),
                        attr(g, "data-target"), classes, points(child(g, "path").getAttribute("d")), badges(g), data(g)));
            } else {
                Element shape = child(g, "rect");
                Box box;
                if (shape != null) {
                    box = new Box(d(shape, "x"), d(shape, "y"), d(shape, "width"), d(shape, "height"));
                } else {
                    Element e = child(g, "ellipse");
                    box = new Box(d(e, "cx") - d(e, "rx"), d(e, "cy") - d(e, "ry"), 2 * d(e, "rx"), 2 * d(e, "ry"));
                }
                List<Text> texts = new ArrayList<>();
                for (Node n = g.getFirstChild(); n != null; n = n.getNextSibling()) {
                    if (n instanceof Element t && t.getLocalName().equals("text")) {
                        texts.add(text(t));
                    }
                }
                shapes.put(g.getAttribute("id"), new Shape(g.getAttribute("id"), g.getAttribute("data-kind"), attr(g, "data-qname"),
                        attr(g, "data-uri"), attr(g, "data-parent"), classes, box, texts, badges(g), data(g)));
            }
        }
    }

    /** Every data- attribute, by its name without the prefix. */
    private static Map<String, String> data(Element g) {
        Map<String, String> data = new LinkedHashMap<>();
        for (int i = 0; i < g.getAttributes().getLength(); i++) {
            Node a = g.getAttributes().item(i);
            if (a.getNodeName().startsWith("data-")) {
                data.put(a.getNodeName().substring(5), a.getNodeValue());
            }
        }
        return data;
    }

    private static List<String> badges(Element g) {
        List<String> badges = new ArrayList<>();
        for (Node n = g.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element b && b.getLocalName().equals("g") && b.getAttribute("class").startsWith("badge")) {
                badges.add(b.getTextContent());
            }
        }
        return badges;
    }

    /** The box a text occupies, measured with the same metrics as the layout. */
    static Text text(Element t) {
        double size = d(t, "font-size");
        boolean bold = "bold".equals(t.getAttribute("font-weight"));
        String content = t.getTextContent();
        double width = TextMetrics.width(content, size, bold);
        double x = d(t, "x");
        String anchor = t.getAttribute("text-anchor");
        if (anchor.equals("end")) {
            x -= width;
        } else if (anchor.equals("middle")) {
            x -= width / 2;
        }
        double y = d(t, "y");
        return new Text(content, new Box(x, y - size * TextMetrics.ASCENT, width, size * (TextMetrics.ASCENT + TextMetrics.DESCENT)));
    }

    private static String attr(Element e, String name) {
        return e.hasAttribute(name) ? e.getAttribute(name) : null;
    }

    private static Element child(Element parent, String name) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getLocalName().equals(name)) {
                return e;
            }
        }
        return null;
    }

    private static double d(Element e, String name) {
        return Double.parseDouble(e.getAttribute(name));
    }

    private static List<double[]> points(String path) {
        List<double[]> points = new ArrayList<>();
        for (String part : path.replace("M", "").split(" L")) {
            String[] xy = part.trim().split(",");
            points.add(new double[] { Double.parseDouble(xy[0]), Double.parseDouble(xy[1]) });
        }
        return points;
    }

    /** The shapes of one kind. */
    List<Shape> ofKind(String kind) {
        return shapes.values().stream().filter(s -> s.kind().equals(kind)).toList();
    }

    /** The shape drawing the element with this qualified name; fails unless exactly one does. */
    Shape byQname(String qname) {
        List<Shape> found = shapes.values().stream().filter(s -> qname.equals(s.qname())).toList();
        if (found.size() != 1) {
            throw new AssertionError(found.size() + " shapes named " + qname);
        }
        return found.get(0);
    }
}
