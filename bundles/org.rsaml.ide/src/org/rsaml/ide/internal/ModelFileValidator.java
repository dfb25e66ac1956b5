/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide.internal;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.RsamlModelValidator;

/** Validates one workspace file and replaces its RsaML problem markers with the findings. */
final class ModelFileValidator {

    private ModelFileValidator() {
    }

    static void validate(IFile file) throws CoreException {
        file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
        String displayName = file.getFullPath().toString();
        try {
            for (Finding finding : findings(file, displayName)) {
                RsamlMarkers.create(file, finding);
            }
        } catch (ModelLoadException e) {
            for (ModelLoadException.Problem problem : e.problems()) {
                Map<String, Object> attributes = new HashMap<>();
                attributes.put(IMarker.SEVERITY, IMarker.SEVERITY_ERROR);
                attributes.put(IMarker.MESSAGE, RsamlMarkers.LOAD_ERROR_RULE_ID + ": " + problem.message());
                attributes.put(IMarker.LINE_NUMBER, Math.max(1, problem.location().line()));
                attributes.put(RsamlMarkers.RULE_ID, RsamlMarkers.LOAD_ERROR_RULE_ID);
                file.createMarker(RsamlMarkers.PROBLEM, attributes);
            }
        } catch (RuntimeException e) {
            // A defect of RsaML, not of the model: say so on the file instead of failing the whole build.
            Platform.getLog(ModelFileValidator.class).log(Status.error("RsaML could not validate " + displayName, e));
            file.createMarker(RsamlMarkers.PROBLEM, Map.of(IMarker.SEVERITY, IMarker.SEVERITY_ERROR, IMarker.MESSAGE,
                    "RsaML could not validate this file (" + e + "); the error log has the details", IMarker.LINE_NUMBER, 1));
        }
    }

    private static List<Finding> findings(IFile file, String displayName) throws ModelLoadException, CoreException {
        IPath location = file.getLocation();
        if (location != null) {
            return RsamlModelValidator.validate(location.toPath(), displayName);
        }
        // Not on the local file system (e.g. a virtual file system): validate a local copy of the content.
        Path copy = null;
        try (InputStream in = file.getContents(true)) {
            copy = Files.createTempFile("rsaml-", "." + file.getFileExtension());
            Files.copy(in, copy, StandardCopyOption.REPLACE_EXISTING);
            return RsamlModelValidator.validate(copy, displayName);
        } catch (IOException e) {
            throw new ModelLoadException(displayName, 0, 0, "the file cannot be read: " + e.getMessage(), e);
        } finally {
            if (copy != null) {
                try {
                    Files.deleteIfExists(copy);
                } catch (IOException e) {
                    copy.toFile().deleteOnExit();
                }
            }
        }
    }
}
