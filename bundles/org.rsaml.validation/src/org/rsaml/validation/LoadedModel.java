/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.model.Architecture;

/** A loaded .rsaml model that knows where in its file each element starts. */
public final class LoadedModel {

    private final Resource resource;
    private final String file;
    private final Path path;
    private final Map<EObject, Long> parserPositions;
    private int[] lineStarts;
    private String text;

    LoadedModel(Resource resource, String file, Path path, Map<EObject, Long> parserPositions) {
        this.resource = resource;
        this.file = file;
        this.path = path;
        this.parserPositions = parserPositions;
    }

    public Resource resource() {
        return resource;
    }

    public Architecture architecture() {
        return (Architecture) resource.getContents().get(0);
    }

    /** The file as the user named it. */
    public String file() {
        return file;
    }

    /** Number of elements whose position is known (every element read from the file). */
    public int elementCount() {
        return parserPositions.size();
    }

    /**
     * The 1-based line and column where the element's start tag begins, or {0, 0} when it was not
     * read from the file. The parser reports where a start tag ends; the file is read again, only
     * when a finding needs it, to move back to the tag's '&lt;'.
     */
    public synchronized int[] locate(EObject element) {
        Long packed = parserPositions.get(element);
        if (packed == null) {
            return new int[] { 0, 0 };
        }
        int line = (int) (packed >>> 32);
        int column = (int) (long) packed;
        if (!loadText()) {
            return new int[] { line, column };
        }
        int offset = Math.min(text.length(), lineStarts[Math.max(0, line - 1)] + Math.max(0, column - 1));
        int start = text.lastIndexOf('<', Math.max(0, offset - 1));
        if (start < 0) {
            return new int[] { line, column };
        }
        int startLine = Arrays.binarySearch(lineStarts, start);
        if (startLine < 0) {
            startLine = -startLine - 2;
        }
        return new int[] { startLine + 1, start - lineStarts[startLine] + 1 };
    }

    private boolean loadText() {
        if (text != null) {
            return true;
        }
        if (path == null) {
            return false;
        }
        try {
            text = new String(Files.readAllBytes(path), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return false;
        }
        int count = 1;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                count++;
            }
        }
        lineStarts = new int[count];
        for (int i = 0, l = 1; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                lineStarts[l++] = i + 1;
            }
        }
        return true;
    }
}
