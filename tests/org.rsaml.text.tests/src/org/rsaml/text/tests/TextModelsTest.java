/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Module;
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.PackageLayout;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/** A textual model is read, checked and located as its XMI twin is. */
class TextModelsTest {

    @TempDir
    Path temp;

    private static final String ROBOT = """
            // A two-layer robot.
            architecture robot {
              declaredLayers 2
              layer perception {
                level 1
                module lidarDriver {
                  type realTime
                  execType periodic
                  period 50 ms
                  deadline 50 ms
                  wcet 5 ms
                  output scan { dataType structured messageType "LaserScan" }
                }
              }
              layer control {
                module localCostmap {
                  execType periodic
                  period 100 ms
                  input scan { dataType structured messageType "LaserScan" }
                }
              }
              /* data flow */
              connect lidarDriver.scan -> localCostmap.scan
            }
            """;

    @Test
    void readsReferencesByShortAndFullNames() throws Exception {
        LoadedModel model = Models.read(temp, "robot.rsa", ROBOT);
        Module driver = model.architecture().getLayers().get(0).getModules().get(0);
        assertEquals(50.0, driver.getPeriod(), "period 50 ms");
        assertEquals(1, model.architecture().getConnections().size(), "one connection");
        assertEquals(driver.getPorts().get(0), model.architecture().getConnections().get(0).getSource(), "lidarDriver.scan is the driver's port");
        LoadedModel full = Models.read(temp, "full.rsa", ROBOT.replace("connect lidarDriver.scan -> localCostmap.scan",
                "connect perception.lidarDriver.scan -> control.localCostmap.scan"));
        assertEquals(null, Models.difference(model.architecture(), full.architecture()), "full and short names name the same ports");
    }

    /**
     * lifecycle on the architecture makes its nodes managed; a module's own lifecycle overrides it,
     * plain included (a module that says plain under a managed architecture keeps saying it), and a
     * module that says nothing follows the architecture. The writer gives back what was written.
     */
    @Test
    void lifecycleOfTheArchitectureAndAModuleThatChoosesOtherwise() throws Exception {
        String text = ROBOT.replace("  declaredLayers 2\n", "  declaredLayers 2\n  lifecycle managed\n")
                .replace("    module localCostmap {\n", "    module localCostmap {\n      lifecycle plain\n");
        LoadedModel model = Models.read(temp, "managed.rsa", text);
        Module driver = model.architecture().getLayers().get(0).getModules().get(0);
        Module costmap = model.architecture().getLayers().get(1).getModules().get(0);
        assertEquals(NodeLifecycle.MANAGED, model.architecture().getLifecycle(), "lifecycle managed on the architecture");
        assertFalse(driver.isSetLifecycle(), "the driver says nothing of its lifecycle");
        assertEquals(NodeLifecycle.MANAGED, driver.effectiveLifecycle(), "the driver follows the architecture");
        assertTrue(costmap.isSetLifecycle(), "the costmap says lifecycle plain");
        assertEquals(NodeLifecycle.PLAIN, costmap.effectiveLifecycle(), "the costmap chose a plain node");
        String written = ModelConverter.toText(model.architecture());
        assertTrue(written.contains("  lifecycle managed\n") && written.contains("      lifecycle plain\n"),
                "both choices are written back:\n" + written);
        assertEquals(null, Models.difference(model.architecture(), Models.read(temp, "again.rsa", written).architecture()),
                "the written text reads back as the same model");
        assertEquals(NodeLifecycle.PLAIN, Models.read(temp, "plain.rsa", ROBOT).architecture().getLayers().get(0).getModules().get(0)
                .effectiveLifecycle(), "without lifecycle, nodes are plain");
    }

    /**
     * packages on the architecture chooses the ROS 2 package layout; without it, one package. The
     * writer gives back what was written, and a layer whose name gives the package name of another
     * is found (RSA-29) at its line of the text.
     */
    @Test
    void packagesOfTheArchitectureAndALayerWhosePackageCollides() throws Exception {
        String text = ROBOT.replace("  declaredLayers 2\n", "  declaredLayers 2\n  packages perLayer\n");
        LoadedModel model = Models.read(temp, "layered.rsa", text);
        assertEquals(PackageLayout.PER_LAYER, model.architecture().getPackages(), "packages perLayer on the architecture");
        String written = ModelConverter.toText(model.architecture());
        assertTrue(written.contains("  packages perLayer\n"), "the layout is written back:\n" + written);
        assertEquals(null, Models.difference(model.architecture(), Models.read(temp, "again.rsa", written).architecture()),
                "the written text reads back as the same model");
        assertEquals(PackageLayout.SINGLE, Models.read(temp, "single.rsa", ROBOT).architecture().getPackages(),
                "without packages, one package");
        String colliding = text.replace("layer control {", "layer Perception {");
        List<Finding> findings = RsamlModelValidator.validate(Models.read(temp, "colliding.rsa", colliding));
        List<String> rsa29 = findings.stream().filter(f -> f.ruleId().equals("RSA-29")).map(f -> f.line() + " " + f.message()).toList();
        assertEquals(2, rsa29.size(), "both layers of package robot_perception are found: " + findings);
        assertTrue(rsa29.get(0).startsWith("5 ") && rsa29.get(0).contains("same ROS 2 package as layer 'Perception'"),
                "the finding of layer perception, at its line: " + rsa29);
    }

    @Test
    void findingsOfTextEqualThoseOfXmiAndPointIntoTheText() throws Exception {
        Path xmi = TestRepository.example("exp2-defects.rsaml");
        List<Finding> expected = RsamlModelValidator.validate(ModelLoader.load(xmi, "exp2-defects.rsaml"));
        Path text = temp.resolve("exp2-defects.rsa");
        ModelConverter.convert(xmi, "exp2-defects.rsaml", text);
        List<String> lines = Files.readAllLines(text);
        List<Finding> actual = RsamlModelValidator.validate(ModelLoader.load(text, "exp2-defects.rsa"));
        assertFalse(expected.isEmpty(), "the defects example has findings");
        assertEquals(expected.stream().map(f -> f.ruleId() + " " + f.severity() + " " + f.qualifiedName() + ": " + f.message()).toList(),
                actual.stream().map(f -> f.ruleId() + " " + f.severity() + " " + f.qualifiedName() + ": " + f.message()).toList(),
                "the same findings, rule ids, severities and messages");
        for (Finding f : actual) {
            assertEquals("exp2-defects.rsa", f.file(), "findings name the text file: " + f);
            assertTrue(f.line() > 0 && f.column() > 0, "a located finding: " + f);
            String simpleName = f.qualifiedName() == null ? "" : f.qualifiedName().replaceAll(".*[^A-Za-z0-9_]", "");
            assertTrue(lines.get(f.line() - 1).contains(simpleName),
                    "the finding points at the line of its element (" + simpleName + "): " + f + " -> " + lines.get(f.line() - 1));
        }
    }

    @Test
    void aSyntaxErrorIsLocated() {
        ModelLoadException e = assertThrows(ModelLoadException.class,
                () -> Models.read(temp, "bad.rsa", "architecture a {\n  layer l {\n    level high\n  }\n}\n"),
                "a syntax error is a load error");
        assertEquals("bad.rsa", e.file(), "the file is named");
        assertEquals(3, e.line(), "the line of 'level high': " + e.getMessage());
        assertTrue(e.column() > 0, "a column: " + e.getMessage());
    }

    @Test
    void anUnresolvedReferenceIsLocatedAndNamed() {
        ModelLoadException e = assertThrows(ModelLoadException.class,
                () -> Models.read(temp, "ref.rsa", ROBOT.replace("connect lidarDriver.scan", "connect lidarDriver.scna")),
                "an unresolved reference is a load error");
        assertEquals(23, e.line(), "the line of the connection: " + e.getMessage());
        assertTrue(e.getMessage().contains("lidarDriver.scna"), "the name that does not resolve is quoted: " + e.getMessage());
    }

    @Test
    void deepNestingIsRefusedBeforeParsing() {
        StringBuilder text = new StringBuilder("architecture a { mission m {\n");
        text.append("goal g {\n".repeat(1200)).append("}\n".repeat(1200)).append("} }\n");
        ModelLoadException e = assertThrows(ModelLoadException.class, () -> Models.read(temp, "deep.rsa", text.toString()),
                "too deep a nesting is a load error");
        assertTrue(e.getMessage().contains("nested more than 1000 levels"), "says why: " + e.getMessage());
        assertEquals(1000, e.line(), "points at the brace one level too deep: " + e.getMessage());
    }

    @Test
    void aNonNumberIsAnErrorNamingIt() {
        ModelLoadException e = assertThrows(ModelLoadException.class,
                () -> Models.read(temp, "num.rsa", "architecture a {\n  declaredLayers 2.5\n}\n"),
                "a non-number is a load error");
        assertEquals(2, e.line(), "the line of the non-number: " + e.getMessage());
        assertTrue(e.getMessage().contains("'2.5' is not a whole number"), "names the value and what it should be: " + e.getMessage());
    }
}
