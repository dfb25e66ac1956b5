/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryIteratorException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.rsaml.model.resource.ModelFormats;
import org.rsaml.validation.ModelLoadException;

/**
 * Turns the paths a user names into model files: a file is taken as it is (whatever its extension,
 * since the user asked for it), a directory contributes every {@code .rsaml} and {@code .rsa} (textual)
 * file below it, in a
 * stable order. Paths keep the spelling the user gave, so reports point where the user looks.
 */
public final class ModelFiles {

    public static final String EXTENSION = ".rsaml";

    /**
     * A model file with the name it is reported under, or, with {@code unusable} set, a named path
     * that gives no model (missing path, directory without models).
     */
    public record Input(Path path, String displayName, ModelLoadException unusable) {
    }

    private ModelFiles() {
    }

    /**
     * @param base  the directory relative paths are resolved against (the working directory)
     * @param paths files and directories as the user named them
     * @return the inputs in the order the user named them, model files without duplicates
     */
    public static List<Input> select(Path base, List<Path> paths) {
        List<Input> entries = new ArrayList<>();
        Set<Path> seen = new HashSet<>();
        for (Path named : paths) {
            String shown = display(named);
            Path path = base.resolve(named);
            if (Files.isDirectory(path)) {
                List<Path> found;
                try {
                    found = modelsUnder(path);
                } catch (IOException | UncheckedIOException e) {
                    entries.add(unusable(shown, "cannot list the directory: " + reason(e)));
                    continue;
                }
                Path folder = realPath(path);
                List<Input> refusedLinks = new ArrayList<>();
                for (Path link : directoryLinksUnder(path)) {
                    Path target = realPath(link);
                    if (folder != null && target != null && !target.startsWith(folder) && hasModels(target)) {
                        // Walking the folder does not follow links to directories; one that leads out is said, as a file link is.
                        refusedLinks.add(unusable(display(named.resolve(path.relativize(link)).normalize()), "refused: a symbolic link"
                                + " to a directory leads out of the folder '" + shown + "' (to " + display(target)
                                + "), so its models are not validated; name the target itself to validate them"));
                    }
                }
                if (found.isEmpty() && refusedLinks.isEmpty()) {
                    entries.add(unusable(shown, "no " + EXTENSION + " (or ." + ModelFormats.TEXT_EXTENSION + ") files in this directory or below it"));
                }
                for (Path file : found) {
                    String fileShown = display(named.resolve(path.relativize(file)).normalize());
                    Path target = realPath(file);
                    if (folder != null && target != null && !target.startsWith(folder)) {
                        // As for references: a folder's models are what is in the folder, not where links lead.
                        entries.add(unusable(fileShown, "refused: a symbolic link leads out of the folder '" + shown
                                + "' (to " + display(target) + "); name the target itself to validate it"));
                        continue;
                    }
                    add(entries, seen, file, fileShown);
                }
                entries.addAll(refusedLinks);
            } else if (Files.exists(path)) {
                add(entries, seen, path, shown);
            } else {
                entries.add(unusable(shown, "no such file or directory"));
            }
        }
        return List.copyOf(entries);
    }

    /** The model files ({@code .rsaml}, {@code .rsa}) under a directory, sorted by path; hidden folders are skipped. */
    public static List<Path> modelsUnder(Path directory) throws IOException {
        try (Stream<Path> walk = Files.walk(directory)) {
            return walk.filter(p -> !hiddenBelow(directory, p)).filter(ModelFiles::isModel).sorted()
                    .toList();
        }
    }

    /** The symbolic links to directories under a directory (not followed by {@link #modelsUnder}), sorted; hidden folders are skipped. */
    private static List<Path> directoryLinksUnder(Path directory) {
        try (Stream<Path> walk = Files.walk(directory)) {
            return walk.filter(p -> !hiddenBelow(directory, p)).filter(p -> Files.isSymbolicLink(p) && Files.isDirectory(p)).sorted().toList();
        } catch (IOException | UncheckedIOException e) {
            return List.of(); // the directory's own listing reports what cannot be read
        }
    }

    /** A model file (or a link to one) by its name. */
    private static boolean isModel(Path p) {
        return p.getFileName() != null && ModelFormats.isModelFile(p.getFileName().toString()) && Files.isRegularFile(p);
    }

    /**
     * Whether a directory holds a model file as {@link #modelsUnder} finds them (hidden files and folders skipped, its
     * own links to directories not followed), stopping at the first. The directory may be a large tree outside the
     * folder (a link to a home folder or a data set), so it is looked into level by level: a folder's own files before
     * any folder below it, and no folder below the level of the first model is read.
     */
    private static boolean hasModels(Path directory) {
        Deque<Path> folders = new ArrayDeque<>(List.of(directory));
        while (!folders.isEmpty()) {
            List<Path> below = new ArrayList<>();
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(folders.removeFirst())) {
                for (Path entry : entries) {
                    if (entry.getFileName().toString().startsWith(".")) {
                        continue;
                    }
                    if (Files.isDirectory(entry, LinkOption.NOFOLLOW_LINKS)) {
                        below.add(entry);
                    } else if (isModel(entry)) {
                        return true;
                    }
                }
            } catch (IOException | DirectoryIteratorException e) {
                // an unreadable part hides no model elsewhere
            }
            Collections.sort(below);
            folders.addAll(below);
        }
        return false;
    }

    private static Path realPath(Path path) {
        try {
            return path.toRealPath();
        } catch (IOException e) {
            return null; // reported when the file is read
        }
    }

    private static boolean hiddenBelow(Path root, Path p) {
        for (Path part : root.relativize(p)) {
            if (part.toString().startsWith(".")) {
                return true;
            }
        }
        return false;
    }

    private static void add(List<Input> entries, Set<Path> seen, Path file, String shown) {
        Path key = file.toAbsolutePath().normalize();
        if (seen.add(key)) {
            entries.add(new Input(file, shown, null));
        }
    }

    private static Input unusable(String shown, String message) {
        return new Input(null, shown, new ModelLoadException(shown, message));
    }

    /** Forward slashes everywhere, so reports read the same on every platform and in SARIF. */
    public static String display(Path path) {
        return path.toString().replace('\\', '/');
    }

    private static String reason(Exception e) {
        Throwable cause = e instanceof UncheckedIOException u ? u.getCause() : e;
        return cause.getMessage() == null ? cause.getClass().getSimpleName() : cause.getMessage();
    }
}
