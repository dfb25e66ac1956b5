/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.tests.SvgDocument.Box;
import org.rsaml.diagram.tests.SvgDocument.Link;
import org.rsaml.diagram.tests.SvgDocument.Shape;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.Layer;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.support.RsamlLabels;

/** The geometry of every example's diagrams, read back from the SVG as a viewer would see it. */
class GeometryTest {

    private static final double TOLERANCE = 0.51;

    /** The model classes each view draws, by EClass name. */
    private static final Map<DiagramView, Set<String>> DRAWN = Map.of(
            DiagramView.ARCHITECTURE, Set.of("Architecture", "Layer", "Module", "Function", "Action", "RTAction", "EntryPort",
                    "OutputPort", "Connection", "Inhibitor", "Suppressor", "Sensor", "Actuator"),
            DiagramView.MISSION, Set.of("Architecture", "Mission", "Goal", "Plan", "Activity", "Supervisor", "Order"));

    static Stream<Arguments> diagrams() throws Exception {
        List<Arguments> all = new ArrayList<>();
        for (String name : Examples.names()) {
            for (DiagramView view : DiagramView.values()) {
                all.add(Arguments.of(name, view));
            }
        }
        return all.stream();
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("diagrams")
    void everyElementIsDrawnExactlyOnce(String name, DiagramView view) throws Exception {
        Examples.Drawn drawn = Examples.draw(name, view);
        SvgDocument svg = new SvgDocument(drawn.svg());
        Map<String, Integer> expected = new HashMap<>();
        List<EObject> all = new ArrayList<>();
        all.add(drawn.model().architecture());
        drawn.model().architecture().eAllContents().forEachRemaining(all::add);
        for (EObject e : all) {
            if (DRAWN.get(view).contains(e.eClass().getName())) {
                expected.merge(RsamlLabels.qualifiedName(e), 1, Integer::sum);
            }
        }
        Map<String, Integer> actual = new HashMap<>();
        svg.shapes.values().forEach(s -> actual.merge(s.qname(), 1, Integer::sum));
        svg.links.stream().filter(l -> l.qname() != null).forEach(l -> actual.merge(l.qname(), 1, Integer::sum));
        assertEquals(expected, actual, "qualified names drawn, with how often");
        Architecture architecture = drawn.model().architecture();
        if (view == DiagramView.ARCHITECTURE || !architecture.getMissions().isEmpty()) {
            assertTrue(expected.size() > 3, "the example draws something in this view");
        }
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("diagrams")
    void siblingsDoNotOverlapAndChildrenStayInside(String name, DiagramView view) throws Exception {
        SvgDocument svg = new SvgDocument(Examples.draw(name, view).svg());
        List<Shape> shapes = new ArrayList<>(svg.shapes.values());
        for (int i = 0; i < shapes.size(); i++) {
            Shape a = shapes.get(i);
            if (a.parent() != null && !isPort(a)) {
                Shape parent = svg.shapes.get(a.parent());
                assertNotNull(parent, a.qname() + " names its parent");
                assertTrue(parent.box().contains(a.box(), TOLERANCE), a.qname() + " " + a.box() + " lies inside " + parent.qname() + " " + parent.box());
            }
            for (int j = i + 1; j < shapes.size(); j++) {
                Shape b = shapes.get(j);
                if (java.util.Objects.equals(a.parent(), b.parent())) {
                    assertFalse(a.box().overlaps(b.box(), TOLERANCE), a.qname() + " " + a.box() + " overlaps " + b.qname() + " " + b.box());
                }
            }
        }
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("diagrams")
    void labelsStayInTheirNodeAndOffOtherNodes(String name, DiagramView view) throws Exception {
        SvgDocument svg = new SvgDocument(Examples.draw(name, view).svg());
        for (Shape shape : svg.shapes.values()) {
            Shape owner = isPort(shape) ? svg.shapes.get(shape.parent()) : shape;
            Set<String> ancestors = ancestors(svg, shape);
            for (SvgDocument.Text text : shape.texts()) {
                assertTrue(owner.box().contains(text.box(), TOLERANCE),
                        "'" + text.text() + "' " + text.box() + " lies inside " + owner.qname() + " " + owner.box());
                for (Shape other : svg.shapes.values()) {
                    if (other != shape && !ancestors.contains(other.id())) {
                        assertFalse(other.box().overlaps(text.box(), TOLERANCE),
                                "'" + text.text() + "' of " + shape.qname() + " overlaps " + other.qname() + " " + other.box());
                    }
                }
            }
        }
    }

    private static Set<String> ancestors(SvgDocument svg, Shape shape) {
        Set<String> ids = new java.util.HashSet<>();
        for (Shape s = shape; s != null && s.parent() != null; s = svg.shapes.get(s.parent())) {
            ids.add(s.parent());
        }
        return ids;
    }

    private static boolean isPort(Shape shape) {
        return shape.kind().endsWith("-port");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("org.rsaml.diagram.tests.Examples#names")
    void portsLieOnTheirModulesBorderEntriesLeftOutputsRight(String name) throws Exception {
        SvgDocument svg = new SvgDocument(Examples.draw(name, DiagramView.ARCHITECTURE).svg());
        for (Shape port : svg.shapes.values()) {
            if (!isPort(port)) {
                continue;
            }
            Box module = svg.shapes.get(port.parent()).box();
            double cx = port.box().x() + port.box().width() / 2;
            double cy = port.box().y() + port.box().height() / 2;
            double side = port.kind().equals("entry-port") ? module.x() : module.right();
            assertEquals(side, cx, TOLERANCE, port.qname() + " is centred on its module's " + (side == module.x() ? "left" : "right") + " border");
            assertTrue(cy > module.y() && cy < module.bottom(), port.qname() + " lies along its module's side");
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("org.rsaml.diagram.tests.Examples#names")
    void linksStartAndEndAtTheirPorts(String name) throws Exception {
        Examples.Drawn drawn = Examples.draw(name, DiagramView.ARCHITECTURE);
        SvgDocument svg = new SvgDocument(drawn.svg());
        Architecture architecture = drawn.model().architecture();
        int checked = 0;
        for (Link link : svg.links) {
            assertTrue(link.points().size() >= 2, link.kind() + " " + link.qname() + " has a route");
            Shape source = svg.byQname(link.source());
            Shape target = svg.byQname(link.target());
            double[] first = link.points().get(0);
            double[] last = link.points().get(link.points().size() - 1);
            if (isPort(source)) {
                assertTrue(source.box().contains(first[0], first[1], TOLERANCE), link.qname() + " starts at its port " + source.qname());
            } else {
                assertTrue(onBorder(source.box(), first), link.kind() + " " + link.qname() + " starts on " + source.qname() + "'s border");
            }
            if (isPort(target)) {
                assertTrue(target.box().contains(last[0], last[1], TOLERANCE), link.qname() + " ends at its port " + target.qname());
            } else {
                assertTrue(onBorder(target.box(), last), link.kind() + " " + link.qname() + " ends on " + target.qname() + "'s border");
            }
            checked++;
        }
        long expected = architecture.getConnections().size() + EcoreUtilCount.count(architecture, SubsumptionLink.class);
        assertEquals(expected, svg.links.stream().filter(l -> l.qname() != null).count(), "connections, inhibitors and suppressors drawn");
        for (Connection connection : architecture.getConnections()) {
            // Connections are named after their ports, which may repeat: find each by its URI fragment.
            String uri = connection.eResource().getURIFragment(connection);
            Link link = svg.links.stream().filter(l -> uri.equals(l.uri())).findFirst().orElseThrow();
            assertEquals(RsamlLabels.qualifiedName(connection.getSource()), link.source(), "the drawn connection starts at its source port");
            assertEquals(RsamlLabels.qualifiedName(connection.getTarget()), link.target(), "the drawn connection ends at its target port");
        }
        assertEquals(svg.links.size(), checked, "every drawn link's ends were checked");
    }

    private static boolean onBorder(Box box, double[] p) {
        boolean inside = box.contains(p[0], p[1], TOLERANCE);
        boolean edge = Math.abs(p[0] - box.x()) <= TOLERANCE || Math.abs(p[0] - box.right()) <= TOLERANCE
                || Math.abs(p[1] - box.y()) <= TOLERANCE || Math.abs(p[1] - box.bottom()) <= TOLERANCE;
        return inside && edge;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("org.rsaml.diagram.tests.Examples#names")
    void layersAreStackedByLevelHighestOnTopSensorsBelow(String name) throws Exception {
        Examples.Drawn drawn = Examples.draw(name, DiagramView.ARCHITECTURE);
        SvgDocument svg = new SvgDocument(drawn.svg());
        List<Layer> layers = new ArrayList<>(drawn.model().architecture().getLayers());
        layers.sort(Comparator.comparingInt(Layer::getLevel).reversed());
        for (int i = 1; i < layers.size(); i++) {
            Box above = svg.byQname(RsamlLabels.qualifiedName(layers.get(i - 1))).box();
            Box below = svg.byQname(RsamlLabels.qualifiedName(layers.get(i))).box();
            if (layers.get(i - 1).getLevel() != layers.get(i).getLevel()) {
                assertTrue(above.bottom() < below.y(), layers.get(i - 1).getName() + " (level " + layers.get(i - 1).getLevel()
                        + ") is drawn above " + layers.get(i).getName() + " (level " + layers.get(i).getLevel() + ")");
            }
        }
        if (!layers.isEmpty()) {
            Box lowest = svg.byQname(RsamlLabels.qualifiedName(layers.get(layers.size() - 1))).box();
            for (Shape sensor : svg.ofKind("sensor")) {
                assertTrue(sensor.box().y() > lowest.bottom(), sensor.qname() + " is below the lowest layer");
            }
            for (Shape actuator : svg.ofKind("actuator")) {
                assertTrue(actuator.box().y() > lowest.y(), actuator.qname() + " is beside or below the lowest layer");
            }
        }
    }

    /** Counts contained elements of a type. */
    static final class EcoreUtilCount {
        static long count(EObject root, Class<?> type) {
            long n = 0;
            for (var it = EcoreUtil.getAllContents(root, false); it.hasNext();) {
                if (type.isInstance(it.next())) {
                    n++;
                }
            }
            return n;
        }
    }
}
