/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.validation.ModelLoadException;

/**
 * A mistake in a textual model gets one error, at its line, in the language's words: what was found, what the place
 * takes (the valid values, the units, the entries of a concept), never the parser's internals.
 */
class SyntaxErrorsTest {

    @TempDir
    Path temp;

    /** The model of each case, with '|' for a line break; the error expected: line, column, message. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', quoteCharacter = '`', textBlock = """
            a word where a whole number goes; architecture a {|  layer l {|    level high|  }|}; 3; 11; 'high' is not a whole number: 'level' takes a whole number, as in 'level 2'
            a value missing; architecture a {|  layer l { level }|}; 2; 19; '}' is not a whole number: 'level' takes a whole number, as in 'level 2'
            an enumeration literal that does not exist; architecture a {|  category foo|}; 2; 12; 'foo' is not a valid value of 'category': write one of centralized, hierarchical, behavioral, hybrid, other
            a misspelt literal inside a module; architecture a {|  layer l { module m { execType periodical } }|}; 2; 33; 'periodical' is not a valid value of 'execType': write one of periodic, sporadic, aperiodic
            an unknown unit; architecture a {|  layer l {|    maxExecTime 5 hours|  }|}; 3; 19; 'hours' is not a unit of time: write one of ns, us, ms, s after the number, as in 'maxExecTime 5 ms'
            a time without its number; architecture a {|  layer l { module m { period ms } }|}; 2; 31; 'ms' is not a time: 'period' takes a number and its unit (ns, us, ms, s), as in 'period 50 ms'
            an attribute the concept does not have; architecture a {|  layer l {|    colour red|  }|}; 3; 5; 'colour' is not part of layer 'l': inside its braces write description, level, maxExecTime, unit, module, or '}' to close it
            a reference missing; architecture a {|  layer l { module m { inhibitor i { trigger } } }|}; 2; 46; '}' is not a reference to an output port: 'trigger' takes a reference to an output port, as in 'trigger name'
            a brace missing at the end; architecture a {|  layer l {|    level 1|; 3; 12; the file ends inside layer 'l': a '}' is missing to close it
            an empty file; ; 1; 1; the file holds no model: a textual RsaML model starts with 'architecture NAME {'
            a second architecture; architecture a { }|architecture b { }; 2; 1; 'architecture' follows the end of the model: a file holds one architecture, and nothing but comments follows its closing '}'
            a string not closed; architecture a {|  description "abc|}; 2; 15; a string in double quotes is not closed: its closing '"' is missing
            an arrow missing; architecture a {|  layer l { module m { output o { } input i { } } }|  connect m.o m.i|}; 3; 15; '->' is missing before 'm'
            """)
    void oneClearErrorAtItsLine(String what, String model, int line, int column, String message) {
        String text = model == null ? "" : model.replace('|', '\n');
        ModelLoadException e = assertThrows(ModelLoadException.class, () -> Models.read(temp, "bad.rsa", text), what + " is refused");
        List<ModelLoadException.Problem> problems = e.problems();
        assertEquals(1, problems.size(), what + ": one error, not a cascade: " + e);
        assertEquals("bad.rsa", e.file(), "the file is named");
        assertEquals(line + ":" + column, e.line() + ":" + e.column(), what + ": the line and column of the mistake: " + e);
        assertEquals(message, e.getMessage(), what);
        for (String internal : List.of("ValueConverter", "RULE_", "mismatched", "viable", "EOF", "null")) {
            assertFalse(e.getMessage().contains(internal), what + ": no parser internals (" + internal + "): " + e);
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', quoteCharacter = '`', textBlock = """
            an unknown port; lidar.scna; 'lidar.scna' names no output port of this file
            a port of the wrong direction; costmap.scan; 'costmap.scan' names no output port of this file
            """)
    void aReferenceThatNamesNothingSaysWhatItMustName(String what, String source, String message) {
        String model = """
                architecture a {
                  layer l {
                    module lidar { output scan { } }
                    module costmap { input scan { } }
                  }
                  connect %s -> costmap.scan
                }
                """.formatted(source);
        ModelLoadException e = assertThrows(ModelLoadException.class, () -> Models.read(temp, "ref.rsa", model), what);
        assertEquals(1, e.problems().size(), what + ": one error: " + e);
        assertEquals(6, e.line(), what + ": the line of the connection: " + e);
        assertTrue(e.getMessage().startsWith(message), what + ": " + e.getMessage());
        assertTrue(e.getMessage().contains("qualified by its containers"), what + ": says how names are written: " + e.getMessage());
    }
}
