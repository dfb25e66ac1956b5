/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.daemon;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Iterator;
import java.util.stream.Stream;

/**
 * What tells the resident process that a command may not have run as in a JVM of its own, whose heap is the JDK's
 * default: its inputs are large for this process's heap, or it came near the heap's limit.
 */
final class HeapLimit {

    private HeapLimit() {
    }

    /**
     * Counts, from now on, every collection after which a long-lived heap pool (the old generation, or the whole heap
     * where the collector has none) is at least 95 % full: the point where the loader gives up on a model as too
     * large for the heap. Young pools (eden, survivor) are routinely full after a minor collection and are not counted.
     */
    static void watch() {
        for (MemoryPoolMXBean pool : longLived()) {
            long max = pool.getUsage().getMax();
            if (max > 0) {
                pool.setCollectionUsageThreshold(max / 20 * 19);
            }
        }
    }

    /** How many collections so far left a long-lived pool at or above its threshold (set by {@link #watch}). */
    static long count() {
        long n = 0;
        for (MemoryPoolMXBean pool : longLived()) {
            if (pool.getCollectionUsageThreshold() > 0) {
                n += pool.getCollectionUsageThresholdCount();
            }
        }
        return n;
    }

    private static Iterable<MemoryPoolMXBean> longLived() {
        return ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(pool -> pool.getType() == MemoryType.HEAP && pool.isCollectionUsageThresholdSupported())
                .filter(pool -> !pool.getName().matches(".*(Eden|Survivor|Young|Nursery).*"))
                .toList();
    }

    /**
     * Whether the files that {@code args} name (relative to {@code workingDirectory}), and those below the folders they
     * name, are together larger than {@code limit} bytes; arguments that name nothing (options, formats) count nothing.
     * Links are not followed below a folder, as validation does not follow them.
     */
    static boolean inputsLarger(Path workingDirectory, String[] args, long limit) {
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
