/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.diagram.TimingMode;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The timing analysis drawn over the architecture: the worst path of each latency requirement over
 * exactly the elements the analysis names, each hop's contribution on its module, every processor's
 * utilisation and verdict, every task's response time on the element it releases.
 */
class TimingOverlayTest {

    private static final String MISSED = "mobile-base-latency-missed.rsaml";

    private record Analysed(LoadedModel model, ArchitectureTiming timing, SvgDocument svg, String text) {
    }

    private static Analysed analyse(String name, TimingMode mode) throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.example(name), "examples/" + name);
        ArchitectureTiming timing = TimingAnalysis.analyse(model.architecture());
        String svg = new RsamlDiagrams(DiagramView.ARCHITECTURE).timing(mode).svg(model.architecture(), RsamlModelValidator.validate(model));
        return new Analysed(model, timing, new SvgDocument(svg), svg);
    }

    @Test
    void theMissedRequirementsWorstPathIsDrawnOverExactlyItsElements() throws Exception {
        Analysed a = analyse(MISSED, TimingMode.AUTO);
        LatencyResult scan = a.timing().latencies().get(0);
        assertEquals("scanToWheels", scan.name(), "the missed example's latency requirement is the one drawn");
        assertEquals(Verdict.MISSES, scan.verdict(), "the example is the missed one");
        assertEquals(57_000_000L, scan.reactionNs(), "40 + 4 + 10 + 3 ms, as the example explains");
        String root = a.model().architecture().getName();

        List<String> hops = new ArrayList<>();
        for (Hop hop : scan.worstPath()) {
            hops.add(root + "/" + hop.label());
        }
        assertEquals(2, hops.size(), "detector, then controller");
        Set<String> onPathModules = new TreeSet<>();
        Set<String> onPathOther = new TreeSet<>();
        for (SvgDocument.Shape s : a.svg().shapes.values()) {
            if (s.classes().contains("latency-path")) {
                assertTrue(s.classes().contains("latency-misses"), s.qname() + " is on a missed path");
                assertEquals("scanToWheels", s.data().get("latency"), s.qname());
                (s.kind().equals("module") ? onPathModules : onPathOther).add(s.qname());
            }
        }
        assertEquals(new TreeSet<>(hops), onPathModules, "the modules drawn on the path are the analysis' worst path");
        assertEquals(Set.of(root + "/laserScanner", root + "/wheelMotors"), onPathOther, "the path's sensor and actuator");

        // The links on the path join the path's elements in order: sensor, hops, actuator.
        List<String> chain = new ArrayList<>();
        chain.add(root + "/laserScanner");
        chain.addAll(hops);
        chain.add(root + "/wheelMotors");
        Set<String> expectedSteps = new LinkedHashSet<>();
        for (int i = 0; i + 1 < chain.size(); i++) {
            expectedSteps.add(chain.get(i) + " -> " + chain.get(i + 1));
        }
        Set<String> drawnSteps = new LinkedHashSet<>();
        for (SvgDocument.Link l : a.svg().links) {
            if (l.classes().contains("latency-path")) {
                drawnSteps.add(module(l.source()) + " -> " + module(l.target()));
            }
        }
        assertEquals(expectedSteps, drawnSteps, "every step of the path is drawn, and nothing else");

        // What each hop adds, on its module.
        for (int i = 0; i < scan.worstPath().size(); i++) {
            Hop hop = scan.worstPath().get(i);
            SvgDocument.Shape module = a.svg().byQname(hops.get(i));
            String expected = "scanToWheels hop " + (i + 1) + ": +" + ms(hop.totalNs()) + " (wait " + ms(hop.waitNs()) + " + response "
                    + ms(hop.responseNs()) + ")";
            SvgDocument.Text text = module.texts().stream().filter(t -> t.text().equals(expected)).findFirst()
                    .orElseThrow(() -> new AssertionError(module.qname() + " shows '" + expected + "': " + module.texts()));
            assertTrue(module.box().contains(text.box(), 0.5), "the hop's line is inside its module");
        }
        String frame = String.join("\n", a.svg().byQname(root).texts().stream().map(SvgDocument.Text::text).toList());
        assertTrue(frame.contains("latency scanToWheels (reaction time at most 50 ms): worst 57 ms: MISSES"), frame);
    }

    /**
     * The path is drawn over the elements the analysis went through, not over others of the same
     * name: a module of the same name in another layer, or (a duplicate name, RSA-09) in the same one.
     */
    @Test
    void thePathFollowsTheModulesNotTheirNames() throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.resource("org.rsaml.diagram.tests", "same-named-modules.rsaml"),
                "same-named-modules.rsaml");
        LatencyResult scan = TimingAnalysis.analyse(model.architecture()).latencies().get(0);
        assertEquals(List.of("navigation/detector", "control/velocityController"), scan.worstPath().stream().map(Hop::label).toList(), "the worst path names the modules the analysis went through by their qualified names");
        assertEquals(model.architecture().getLayers().get(0).getModules().get(1), scan.worstPath().get(0).module(),
                "the hop is the second navigation detector, the one that reads the laser");
        SvgDocument svg = new SvgDocument(new RsamlDiagrams(DiagramView.ARCHITECTURE).timing(TimingMode.AUTO)
                .svg(model.architecture(), RsamlModelValidator.validate(model)));
        SvgDocument.Link connection = svg.links.stream().filter(l -> "//@connections.0".equals(l.uri())).findFirst()
                .orElseThrow(() -> new AssertionError("the connection is drawn"));
        assertTrue(connection.classes().contains("latency-path"), "the path's connection, from the second detector: " + connection);
        for (SvgDocument.Shape s : svg.ofKind("module")) {
            if (s.qname().equals("dupes/control/detector")) {
                assertFalse(s.classes().contains("latency-path"), "the control layer's detector is on no path: " + s);
            }
        }
    }

    /** The page lists every path of a requirement with its own bounds, and the paths a requirement names. */
    @Test
    void everyPathIsListedWithItsBound() throws Exception {
        String name = "latency-named-paths.rsaml";
        LoadedModel model = ModelLoader.load(TestRepository.resource("org.rsaml.analysis.tests", name), name);
        String html = new RsamlDiagrams(DiagramView.ARCHITECTURE).timing(TimingMode.AUTO).html(model.architecture(), name,
                RsamlModelValidator.validate(model)).replace("&gt;", ">").replace("&#62;", ">");
        assertTrue(html.contains("every path, the longest first:"), html);
        assertTrue(html.contains("- deliberative/planner +1.15 s -> reactive/avoid +65 ms -> control/drive +12 ms: reaction time"
                + " 1.227 s, data age 1.237 s"), "the planner's path with its bounds: " + html);
        assertTrue(html.contains("- deliberative/monitor +21 ms -> deliberative/monitor.halt +0 ns -> control/drive +12 ms:"
                + " reaction time 33 ms, data age 43 ms"), "the safety chain through the inhibitor with its bounds");
        assertTrue(html.contains("the paths through deliberative/monitor, then inhibitor deliberative/monitor.halt"),
                "the safety requirement's named path");
    }

    /**
     * Beside the worst path, each branch shows what it takes: every module and connection on a path of the requirement carries
     * the worst bound of the paths through it, and a module off the worst path says it in a line.
     */
    @Test
    void eachModuleAndConnectionOnAPathCarriesTheWorstBoundThroughIt() throws Exception {
        String name = "latency-named-paths.rsaml";
        LoadedModel model = ModelLoader.load(TestRepository.resource("org.rsaml.analysis.tests", name), name);
        String root = model.architecture().getName();
        SvgDocument svg = new SvgDocument(new RsamlDiagrams(DiagramView.ARCHITECTURE).timing(TimingMode.AUTO)
                .svg(model.architecture(), RsamlModelValidator.validate(model)));
        // scanToWheels: planner, avoid, drive 1.227 s (the worst); detector, avoid, drive 132 ms; monitor, halt, drive 33 ms
        assertEquals("scanToWheels: 132 ms", svg.byQname(root + "/reactive/detector").data().get("latency-worst"),
                "the detector's branch takes 132 ms");
        assertEquals("scanToWheels: 33 ms", svg.byQname(root + "/deliberative/monitor").data().get("latency-worst"),
                "the monitor's branch, through the inhibitor, takes 33 ms");
        assertEquals("scanToWheels: 1.227 s", svg.byQname(root + "/reactive/avoid").data().get("latency-worst"),
                "avoid is on the worst path too: its worst is the requirement's");
        List<String> detector = svg.byQname(root + "/reactive/detector").texts().stream().map(SvgDocument.Text::text).toList();
        assertTrue(detector.contains("scanToWheels: the paths through here take at most 132 ms"), "the detector's line: " + detector);
        List<String> planner = svg.byQname(root + "/deliberative/planner").texts().stream().map(SvgDocument.Text::text).toList();
        assertFalse(planner.stream().anyMatch(t -> t.contains("paths through here")), "the worst path's modules show their hops: " + planner);
        SvgDocument.Link fromDetector = svg.links.stream().filter(l -> module(l.source()).equals(root + "/reactive/detector")
                && module(l.target()).equals(root + "/reactive/avoid")).findFirst()
                .orElseThrow(() -> new AssertionError("the detector's connection to avoid is drawn"));
        assertEquals("scanToWheels: 132 ms", fromDetector.data().get("latency-worst"), "the connection's worst is its branch's: " + fromDetector);
        SvgDocument.Link halt = svg.links.stream().filter(l -> l.kind().equals("inhibitor")).findFirst()
                .orElseThrow(() -> new AssertionError("the monitor's inhibitor is drawn"));
        assertTrue(String.valueOf(halt.data().get("latency-worst")).startsWith("scanToWheels: 33 ms"),
                "the inhibitor the monitor's path passes carries its bound: " + halt);
    }

    /**
     * Of two connections between the same two modules, only the one a path takes carries its bound: the requirement
     * starts at e.o1, so e.o2's connection to r is on no path of it.
     */
    @Test
    void onlyTheConnectionAPathTakesCarriesItsBound(@TempDir Path tmp) throws Exception {
        String port = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";
        String text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\""
                + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"two\""
                + " declaredLayers=\"1\">\n<layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n"
                + "<modules name=\"e\" type=\"realTime\" period=\"100.0\" execDuration=\"1.0\" execType=\"periodic\">"
                + "<ports xsi:type=\"rsaml:OutputPort\" name=\"o1\" dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o2\""
                + " dataType=\"numeric\"/></modules>\n"
                + "<modules name=\"q\" execDuration=\"0.1\" execType=\"sporadic\" period=\"20.0\"><ports xsi:type=\"rsaml:EntryPort\" name=\"i\""
                + " dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n"
                + "<modules name=\"r\" execDuration=\"0.1\" execType=\"sporadic\" period=\"10.0\" actuators=\"//@actuators[name='t']\">"
                + "<ports xsi:type=\"rsaml:EntryPort\" name=\"i1\" dataType=\"numeric\"/><ports xsi:type=\"rsaml:EntryPort\" name=\"i2\""
                + " dataType=\"numeric\"/><ports xsi:type=\"rsaml:EntryPort\" name=\"i3\" dataType=\"numeric\"/></modules>\n</layers>\n"
                + connection(port, "e", "o1", "r", "i1") + connection(port, "e", "o2", "r", "i2") + connection(port, "e", "o1", "q", "i")
                + connection(port, "q", "o", "r", "i3")
                + "<actuators name=\"t\" timeUnit=\"ms\" period=\"10.0\"/>\n<latencyRequirements name=\"fromO1\" timeUnit=\"ms\" source=\""
                + port.formatted("e", "o1") + "\" target=\"//@actuators[name='t']\" maxLatency=\"1000.0\"/>\n</rsaml:Architecture>\n";
        Path file = tmp.resolve("two-connections.rsaml");
        Files.writeString(file, text);
        LoadedModel model = ModelLoader.load(file, "two-connections.rsaml");
        SvgDocument svg = new SvgDocument(new RsamlDiagrams(DiagramView.ARCHITECTURE).timing(TimingMode.AUTO)
                .svg(model.architecture(), RsamlModelValidator.validate(model)));
        List<SvgDocument.Link> eToR = svg.links.stream().filter(l -> module(l.source()).equals("two/l/e") && module(l.target()).equals("two/l/r"))
                .toList();
        assertEquals(2, eToR.size(), "both connections from e to r are drawn: " + svg.links);
        for (SvgDocument.Link l : eToR) {
            boolean taken = l.source().endsWith("/o1");
            assertEquals(taken, l.data().containsKey("latency-worst"),
                    (taken ? "the connection from o1, which the paths take, carries their bound: " : "the one from o2, on no path, carries none: ")
                            + l);
        }
    }

    private static String connection(String port, String from, String out, String to, String in) {
        return "<connections source=\"" + port.formatted(from, out) + "\" target=\"" + port.formatted(to, in) + "\"/>\n";
    }

    @Test
    void aMetRequirementsPathIsDrawnWithoutTheMissStyle() throws Exception {
        Analysed a = analyse("mobile-base-latency.rsaml", TimingMode.AUTO);
        LatencyResult scan = a.timing().latencies().get(0);
        assertEquals(Verdict.MEETS, scan.verdict(), "mobile-base-latency's requirement is met");
        Set<String> expected = new TreeSet<>();
        for (Hop hop : scan.worstPath()) {
            expected.add(a.model().architecture().getName() + "/" + hop.label());
        }
        Set<String> drawn = new TreeSet<>();
        for (SvgDocument.Shape s : a.svg().ofKind("module")) {
            if (s.classes().contains("latency-path")) {
                drawn.add(s.qname());
            }
            assertFalse(s.classes().contains("latency-misses"), s.qname());
        }
        assertEquals(expected, drawn, "exactly the worst path's modules are drawn as the latency path");
    }

    @Test
    void utilisationVerdictsAndResponseTimesAreTheAnalysis() throws Exception {
        for (String name : List.of(MISSED, "mobile-base-latency.rsaml")) {
            Analysed a = analyse(name, TimingMode.AUTO);
            List<String> frame = a.svg().byQname(a.model().architecture().getName()).texts().stream().map(SvgDocument.Text::text).toList();
            assertEquals(2, a.timing().processors().size(), name + " deploys on two cores");
            for (ProcessorTiming p : a.timing().processors()) {
                double sum = 0;
                for (TaskResult t : p.result().tasks()) {
                    sum += (double) t.task().cost() / t.task().period();
                }
                assertEquals(sum, p.result().utilisation(), 1e-12, "utilisation is the sum of C/T");
                String line = "processor " + p.name() + " (" + p.result().policy().label() + "): utilisation "
                        + String.format(java.util.Locale.ROOT, "%.4f", sum) + ", " + p.result().tasks().size() + " tasks: "
                        + TimingText.word(p.result().verdict());
                assertTrue(frame.contains(line), name + " shows '" + line + "' in " + frame);
                for (int i = 0; i < p.sources().size(); i++) {
                    TaskSource s = p.sources().get(i);
                    TaskResult t = p.result().tasks().get(i);
                    SvgDocument.Shape shape = a.svg().byQname(RsamlLabels.qualifiedName(s.element()));
                    String expected = "WCRT " + ms(t.responseTime().getAsLong()) + " of deadline " + ms(t.task().deadline()) + ": "
                            + TimingText.word(t.verdict());
                    assertTrue(shape.texts().stream().anyMatch(x -> x.text().equals(expected)), shape.qname() + " shows " + expected);
                }
                for (org.rsaml.model.Module m : p.element().getModules()) {
                    assertTrue(a.svg().byQname(RsamlLabels.qualifiedName(m)).texts().stream()
                            .anyMatch(x -> x.text().equals("on processor " + p.name())), "module " + m.getName() + " names its processor");
                }
            }
        }
    }

    @Test
    void drawnByDefaultOnlyWhenTheModelAsksATimingQuestion() throws Exception {
        Analysed plain = analyse("exp1-hybrid.rsaml", TimingMode.AUTO);
        assertFalse(plain.text().contains("utilisation"), "no processors, no latency requirements: no timing drawn");
        Analysed forced = analyse("exp1-hybrid.rsaml", TimingMode.ON);
        assertTrue(forced.text().contains("processor default ("), "--timing draws the default processor");
        Analysed off = analyse(MISSED, TimingMode.OFF);
        assertFalse(off.text().contains("utilisation"), "--no-timing draws no utilisation");
        assertTrue(off.svg().shapes.values().stream().noneMatch(s -> s.classes().contains("latency-path"))
                && off.svg().links.stream().noneMatch(l -> l.classes().contains("latency-path")), "--no-timing draws no path");
        assertEquals(Examples.draw("exp1-hybrid.rsaml", DiagramView.ARCHITECTURE).svg(), plain.text(), "with no timing question, the automatic mode draws exactly the plain diagram");
        assertNotEquals(off.text(), analyse(MISSED, TimingMode.ON).text(), "--timing on the missed example draws something --no-timing does not");
    }

    @Test
    void theHtmlPageListsTheTimingAndPointsAtThePath(@TempDir Path dir) throws Exception {
        Path first = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(TestRepository.example(MISSED), "examples/" + MISSED, DiagramFormat.HTML,
                dir.resolve("a"));
        Path second = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(TestRepository.example(MISSED), "examples/" + MISSED, DiagramFormat.HTML,
                dir.resolve("b"));
        String html = Files.readString(first);
        assertEquals(html, Files.readString(second), "the same model gives the same page");
        assertTrue(html.contains("<h2>Timing</h2>"), "a Timing section");
        Matcher item = Pattern.compile("<li class=\"overlay-item overlay-misses\" tabindex=\"0\" data-targets=\"([^\"]*)\"><span class=\"text\">"
                + Pattern.quote("latency scanToWheels (reaction time at most 50 ms): worst 57 ms: MISSES")).matcher(html);
        assertTrue(item.find(), "the missed requirement is listed");
        Set<String> targets = Set.of(item.group(1).split(" "));
        Set<String> onPath = new TreeSet<>();
        Matcher g = Pattern.compile("<g id=\"(el-\\d+)\" class=\"([^\"]*)\"").matcher(html);
        while (g.find()) {
            if (Set.of(g.group(2).split(" ")).contains("latency-path")) {
                onPath.add(g.group(1));
            }
        }
        assertEquals(onPath, new TreeSet<>(targets), "the item points at the elements drawn on the path");
    }

    /** The module a link's end belongs to (a port's module), or the device itself. */
    private static String module(String qname) {
        String[] parts = qname.split("/");
        return parts.length == 4 ? String.join("/", List.of(parts).subList(0, 3)) : qname;
    }

    /** Whole milliseconds in this example, so that the figure is checked independently of the formatting code. */
    private static String ms(long ns) {
        assertEquals(0, ns % 1_000_000, ns + " ns is a whole number of milliseconds");
        return ns / 1_000_000 + " ms";
    }
}
