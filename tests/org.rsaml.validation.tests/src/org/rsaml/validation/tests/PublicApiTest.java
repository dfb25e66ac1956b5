/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Type;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Rules;

/**
 * What users of org.rsaml.validation program against (the exported package, not the x-internal
 * one) never hands them an internal type: every public method and field of every public class
 * speaks in API types only.
 */
class PublicApiTest {

    @Test
    void thePublicApiExposesNoInternalType() throws Exception {
        String pkg = Rules.class.getPackageName();
        List<String> classes = new ArrayList<>();
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("bundles/org.rsaml.validation/src/" + pkg.replace('.', '/')))) {
            files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".java"))
                    .forEach(n -> classes.add(pkg + "." + n.substring(0, n.length() - ".java".length())));
        }
        assertTrue(classes.size() >= 8, classes.toString());
        List<String> leaks = new ArrayList<>();
        for (String name : classes) {
            Class<?> type = Class.forName(name, false, Rules.class.getClassLoader());
            check(type, leaks);
            for (Class<?> nested : type.getDeclaredClasses()) {
                if (Modifier.isPublic(nested.getModifiers())) {
                    check(nested, leaks);
                }
            }
        }
        assertEquals(List.of(), leaks, "the public API exposes no internal type");
    }

    private static void check(Class<?> type, List<String> leaks) {
        if (!Modifier.isPublic(type.getModifiers())) {
            return;
        }
        for (Method m : type.getDeclaredMethods()) {
            if (Modifier.isPublic(m.getModifiers()) || Modifier.isProtected(m.getModifiers())) {
                List<Type> used = new ArrayList<>(List.of(m.getGenericParameterTypes()));
                used.add(m.getGenericReturnType());
                for (Type t : used) {
                    if (t.getTypeName().contains(".internal.")) {
                        leaks.add(type.getSimpleName() + "." + m.getName() + " uses " + t.getTypeName());
                    }
                }
            }
        }
        for (Field f : type.getDeclaredFields()) {
            if ((Modifier.isPublic(f.getModifiers()) || Modifier.isProtected(f.getModifiers()))
                    && f.getGenericType().getTypeName().contains(".internal.")) {
                leaks.add(type.getSimpleName() + "." + f.getName() + " is a " + f.getGenericType().getTypeName());
            }
        }
        Type superclass = type.getGenericSuperclass();
        if (superclass != null && superclass.getTypeName().contains(".internal.")) {
            leaks.add(type.getSimpleName() + " extends " + superclass.getTypeName());
        }
    }
}
