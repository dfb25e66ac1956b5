/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code rsaml convert}, and the other commands taking the textual models it writes as they take XMI. */
class ConvertCommandTest {

    @TempDir
    Path temp;

    @Test
    void convertsToTextAndValidateFindsTheSameDefectsInIt() throws Exception {
        Cli.Result converted = Cli.run("convert", "examples/exp2-defects.rsaml", temp.resolve("exp2-defects.rsa").toString());
        assertEquals(0, converted.code(), converted.toString());
        String text = Files.readString(temp.resolve("exp2-defects.rsa"));
        assertTrue(text.startsWith("architecture "), "a textual model:\n" + text);

        Cli.Result xmi = Cli.run("validate", "examples/exp2-defects.rsaml");
        Cli.Result rsa = Cli.runIn(temp, "validate", "exp2-defects.rsa");
        assertEquals(xmi.code(), rsa.code(), "the same verdict\n" + xmi + rsa);
        List<String> expected = ValidateCommandTest.findingLines(xmi.outLines()).stream()
                .map(l -> l.replaceFirst("^examples/exp2-defects.rsaml:\\d+:\\d+: ", "")).toList();
        List<String> actual = ValidateCommandTest.findingLines(rsa.outLines()).stream()
                .map(l -> l.replaceFirst("^exp2-defects.rsa:\\d+:\\d+: ", "")).toList();
        assertEquals(expected, actual, "the same findings, rule ids and messages\n" + rsa);
        for (String line : ValidateCommandTest.findingLines(rsa.outLines())) {
            assertTrue(line.matches("exp2-defects\\.rsa:[1-9]\\d*:[1-9]\\d*: .*"), "located in the text: " + line);
        }
    }

    @Test
    void aFolderOfTextualModelsIsValidatedAndConvertedBack() throws Exception {
        assertEquals(0, Cli.run("convert", "examples/exp3-task-interpreter.rsaml", temp.resolve("models/exp3.rsa").toString()).code(), "convert writes the textual model");
        Cli.Result folder = Cli.runIn(temp, "validate", "models");
        assertEquals(0, folder.code(), folder.toString());
        assertTrue(folder.out().contains("models/exp3.rsa: no findings"), "the .rsa file is found in the folder:\n" + folder);

        Cli.Result back = Cli.runIn(temp, "convert", "models/exp3.rsa", "exp3.rsaml");
        assertEquals(0, back.code(), back.toString());
        assertEquals("wrote exp3.rsaml\n", back.out(), back.toString());
        Cli.Result again = Cli.runIn(temp, "validate", "exp3.rsaml");
        assertEquals(0, again.code(), again.toString());
    }

    @Test
    void aBrokenTextIsReportedWithItsLineAndNothingIsWritten() throws Exception {
        Files.writeString(temp.resolve("bad.rsa"), "architecture robot {\n  layer control {\n    level high\n  }\n}\n");
        Cli.Result result = Cli.runIn(temp, "convert", "bad.rsa", "bad.rsaml");
        assertEquals(2, result.code(), result.toString());
        assertTrue(result.err().startsWith("bad.rsa:3:"), "file:line:column of the error: " + result.err());
        assertFalse(result.err().contains("\tat "), "no stack trace: " + result.err());
        assertFalse(Files.exists(temp.resolve("bad.rsaml")), "nothing is written");
    }

    @Test
    void aFolderOrTheInputItselfIsRefusedAsOutputAndAFolderAsInput() throws Exception {
        Files.copy(Cli.ROOT.resolve("examples/exp1-hybrid.rsaml"), temp.resolve("exp1.rsaml"));
        String before = Files.readString(temp.resolve("exp1.rsaml"));
        Files.createDirectories(temp.resolve("out.rsa"));

        Cli.Result folderOut = Cli.runIn(temp, "convert", "exp1.rsaml", "out.rsa");
        assertEquals(2, folderOut.code(), folderOut.toString());
        assertEquals("out.rsa: error: cannot be written: is a directory; name the file to write\n", folderOut.err(), folderOut.toString());
        assertTrue(Files.isDirectory(temp.resolve("out.rsa")), "the folder is left as it was");

        Cli.Result itself = Cli.runIn(temp, "convert", "exp1.rsaml", "./exp1.rsaml");
        assertEquals(2, itself.code(), itself.toString());
        assertEquals("./exp1.rsaml: error: cannot be written: is the input itself; name another file\n", itself.err(), itself.toString());
        assertEquals(before, Files.readString(temp.resolve("exp1.rsaml")), "the input is left as it was");

        Cli.Result folderIn = Cli.runIn(temp, "convert", "out.rsa", "x.rsaml");
        assertEquals(2, folderIn.code(), folderIn.toString());
        assertTrue(folderIn.err().startsWith("out.rsa") && folderIn.err().contains("is a directory"), "the input named, and why: " + folderIn);
        assertFalse(folderIn.err().contains("\tat "), "no stack trace: " + folderIn);
        assertFalse(Files.exists(temp.resolve("x.rsaml")), "nothing is written");
    }
}
