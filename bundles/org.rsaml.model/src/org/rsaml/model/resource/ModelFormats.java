/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.IOException;
import java.util.Locale;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.function.Predicate;

import org.eclipse.emf.ecore.resource.Resource;

/**
 * The two syntaxes of an RsaML model file: XMI ({@code .rsaml}, the default) and text ({@code .rsa}).
 * Both load into the same model. The textual syntax lives in its own bundle; outside OSGi it is found
 * through {@link java.util.ServiceLoader} ({@link Syntax}), inside OSGi through its plugin.xml.
 */
public final class ModelFormats {

    /** The extension of XMI model files, without the dot. */
    public static final String XMI_EXTENSION = "rsaml";

    /** The extension of textual model files, without the dot. */
    public static final String TEXT_EXTENSION = "rsa";

    /** A syntax other than XMI, registered for its file extension by {@link RsamlStandaloneSetup}. */
    public interface Syntax {
        String fileExtension();

        Resource.Factory resourceFactory();
    }

    private ModelFormats() {
    }

    /** Whether the file name ends with the textual syntax's extension (any case). */
    public static boolean isText(String fileName) {
        return fileName != null && fileName.toLowerCase(Locale.ROOT).endsWith("." + TEXT_EXTENSION);
    }

    /** Whether the file name ends with one of the model extensions (any case). */
    public static boolean isModelFile(String fileName) {
        return fileName != null && (fileName.toLowerCase(Locale.ROOT).endsWith("." + XMI_EXTENSION) || isText(fileName));
    }

    /**
     * Refuses to read a file the loading policy does not let RsaML open (not a regular local file, larger
     * than {@link RsamlResource#OPTION_MAX_FILE_SIZE} allows): the same policy for every syntax, checked
     * before the resource reads anything. The refusal is recorded as the resource's one error, so that
     * whoever follows a reference to it can say why it failed, and thrown. The text an editor holds
     * ({@link RsamlResource#OPTION_EDITOR_TEXT}) is not opened, and not refused.
     */
    @SuppressWarnings("unchecked")
    public static void refuseUnopenable(Resource resource, Map<?, ?> options) throws IOException {
        if (options != null && options.get(RsamlResource.OPTION_EDITOR_TEXT) instanceof Predicate<?> editor
                && ((Predicate<Object>) editor).test(resource.getURI())) {
            return; // the editor's text: nothing is opened
        }
        long limit = options != null && options.get(RsamlResource.OPTION_MAX_FILE_SIZE) instanceof Number n ? n.longValue()
                : RsamlResource.DEFAULT_MAX_FILE_SIZE;
        String refusal = LoadPolicy.refuseToOpen(resource.getURI(), limit);
        if (refusal != null) {
            resource.getErrors().clear();
            LoadProblem problem = new LoadProblem(refusal, resource.getURI().toString(), 0, 0);
            resource.getErrors().add(problem);
            throw new Resource.IOWrappedException(problem);
        }
    }

    /** Puts the factories of the syntaxes on the class path into the map, leaving registered ones alone. */
    static void registerSyntaxes(Map<String, Object> factories) {
        try {
            for (Syntax syntax : ServiceLoader.load(Syntax.class, ModelFormats.class.getClassLoader())) {
                if (!factories.containsKey(syntax.fileExtension())) {
                    factories.put(syntax.fileExtension(), syntax.resourceFactory());
                }
            }
        } catch (ServiceConfigurationError e) {
            // A syntax that cannot be loaded is simply not there; its files then fail to load, saying so.
        }
    }
}
