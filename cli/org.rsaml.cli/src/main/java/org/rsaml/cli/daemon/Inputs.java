/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.daemon;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Iterator;
import java.util.stream.Stream;

/** The size of a command's inputs, for the resident process to send large ones to a JVM of their own. */
final class Inputs {

    private Inputs() {
    }

    /**
     * Whether the files that {@code args} name (relative to {@code workingDirectory}), and those below the folders they
     * name, are together larger than {@code limit} bytes; arguments that name nothing (options, formats) count nothing.
     * Links are not followed below a folder, as validation does not follow them.
     */
    static boolean larger(Path workingDirectory, String[] args, long limit) {
        long total = 0;
        for (String arg : args) {
            if (arg.startsWith("-")) {
                continue;
            }
            Path path;
            try {
                path = workingDirectory.resolve(arg);
            } catch (InvalidPathException e) {
                continue;
            }
            try {
                BasicFileAttributes attributes = Files.readAttributes(path, BasicFileAttributes.class);
                if (attributes.isRegularFile()) {
                    total += attributes.size();
                } else if (attributes.isDirectory()) {
                    try (Stream<Path> files = Files.walk(path)) {
                        for (Iterator<Path> it = files.iterator(); it.hasNext() && total <= limit;) {
                            Path file = it.next();
                            if (Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
                                total += Files.size(file);
                            }
                        }
                    }
                }
            } catch (IOException | UncheckedIOException | SecurityException e) {
                // Unreadable: the command says so, wherever it runs.
            }
            if (total > limit) {
                return true;
            }
        }
        return false;
    }
}
