/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.model.resource.ModelFormats;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/**
 * Every example and every model of the validation fixtures and of the command line's hostile inputs (a file that does
 * not load is refused by the converter with the loader's message) converts XMI to text and back to an equal
 * model, and text to XMI and back to the same text.
 */
class RoundTripTest {

    @TempDir
    Path temp;

    static Stream<Path> models() throws IOException {
        Path root = TestRepository.root();
        List<Path> dirs = List.of(root.resolve("examples"), root.resolve("tests/org.rsaml.validation.tests/resources"),
                root.resolve("tests/org.rsaml.cli.tests/resources/inputs"));
        Stream<Path> all = Stream.empty();
        for (Path dir : dirs) {
            try (Stream<Path> walk = Files.walk(dir)) {
                List<Path> files = walk.filter(p -> p.toString().endsWith("." + ModelFormats.XMI_EXTENSION)).sorted().toList();
                all = Stream.concat(all, files.stream());
            }
        }
        return all;
    }

    @Test
    void theFixturesAreThere() throws IOException {
        assertTrue(models().count() >= 60, "the examples and the validation fixtures are found under " + TestRepository.root());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("models")
    void convertsBothWaysLosslessly(Path xmi) throws Exception {
        String shown = TestRepository.root().relativize(xmi).toString();
        LoadedModel original;
        try {
            original = ModelLoader.load(xmi, shown);
        } catch (ModelLoadException e) {
            // A fixture of a load error: the converter says the same as every command.
            ModelLoadException thrown = org.junit.jupiter.api.Assertions.assertThrows(ModelLoadException.class,
                    () -> ModelConverter.convert(xmi, shown, temp.resolve("out.rsa")), shown);
            assertEquals(e.getMessage(), thrown.getMessage(), "the converter reports the load error of " + shown);
            assertTrue(Files.notExists(temp.resolve("out.rsa")), "nothing is written for " + shown);
            return;
        }
        Path text = temp.resolve("model.rsa");
        ModelConverter.convert(xmi, shown, text);
        String written = Files.readString(text, StandardCharsets.UTF_8);

        LoadedModel fromText = ModelLoader.load(text, "model.rsa");
        assertNull(Models.difference(original.architecture(), fromText.architecture()),
                () -> shown + ": XMI -> text -> model differs; the text:\n" + written);

        Path back = temp.resolve("back.rsaml");
        ModelConverter.convert(text, "model.rsa", back);
        LoadedModel fromXmi = ModelLoader.load(back, "back.rsaml");
        assertNull(Models.difference(original.architecture(), fromXmi.architecture()), () -> shown + ": XMI -> text -> XMI differs");

        assertEquals(written, ModelConverter.toText(fromXmi.architecture()), shown + ": text -> XMI -> text gives other text");
    }

    @Test
    void convertingOverAFileReplacesItWholeNeverRewritingItInPlace() throws Exception {
        Path text = temp.resolve("exp2-defects.rsa");
        String edited = "// the architect's text, being edited\n";
        Files.writeString(text, edited);
        // A second name of the same file: what a reader holding the old file, or an editor's buffer of it, keeps.
        Path held = temp.resolve("held.rsa");
        Files.createLink(held, text);
        ModelConverter.convert(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml", text);
        assertEquals(edited, Files.readString(held),
                "the old file is replaced, not truncated and rewritten in place: a failed write would leave it whole");
        assertNull(Models.difference(ModelLoader.load(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml").architecture(),
                ModelLoader.load(text, "exp2-defects.rsa").architecture()), "the converted model is in its place");
        try (Stream<Path> files = Files.list(temp)) {
            assertEquals(List.of("exp2-defects.rsa", "held.rsa"), files.map(f -> f.getFileName().toString()).sorted().toList(),
                    "no temporary file is left beside it");
        }
    }
}
