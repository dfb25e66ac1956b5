/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.convert;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.rsaml.model.Architecture;
import org.rsaml.model.resource.ModelFormats;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.model.support.AtomicFiles;
import org.rsaml.text.RsamlTextStandaloneSetup;
import org.rsaml.text.serializer.RsamlTextWriter;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/**
 * Converts a model between its two syntaxes, XMI ({@code .rsaml}) and text ({@code .rsa}), each way
 * losslessly: the model read back from the output equals the input's ({@link EcoreUtil#equals}). The
 * input is read as every command reads it ({@link ModelLoader}); the output is written only when the
 * whole of it could be made.
 *
 * <pre>
 * ModelConverter.convert(Path.of("robot.rsaml"), "robot.rsaml", Path.of("robot.rsa"));
 * </pre>
 */
public final class ModelConverter {

    private ModelConverter() {
    }

    /**
     * Reads {@code input} (reported as {@code inputShown}) and writes the same model to {@code output}
     * in the syntax of the output's extension ({@code .rsa}: text, anything else: XMI). An output that is a
     * directory or the input itself is refused before anything is read; an input that is not a regular file is
     * refused by the loader.
     *
     * @throws ModelLoadException the input cannot be read, or the model cannot be written in the output's syntax
     * @throws IOException        the output cannot be written (its message says why, for the output's name to precede it)
     */
    public static void convert(Path input, String inputShown, Path output) throws ModelLoadException, IOException {
        if (Files.isDirectory(output)) {
            throw new IOException("is a directory; name the file to write");
        }
        if (Files.exists(output) && Files.exists(input) && Files.isSameFile(input, output)) {
            throw new IOException("is the input itself; name another file");
        }
        LoadedModel model = ModelLoader.load(input, inputShown);
        String converted;
        try {
            converted = ModelFormats.isText(output.toString()) ? toText(model.architecture()) : toXmi(model.architecture(), output);
        } catch (RsamlTextWriter.UnwritableModelException e) {
            throw new ModelLoadException(inputShown, e.getMessage());
        }
        // Replaced whole: a failed write leaves the file the user had, never a truncated model.
        try {
            AtomicFiles.writeString(output, converted);
        } catch (IOException e) {
            throw new IOException(AtomicFiles.reason(e, output), e);
        }
    }

    /** The model in the textual syntax, in its canonical layout. */
    public static String toText(Architecture architecture) {
        return RsamlTextStandaloneSetup.injector().getInstance(RsamlTextWriter.class).write(architecture);
    }

    private static String toXmi(Architecture architecture, Path output) throws IOException {
        ResourceSet resourceSet = RsamlStandaloneSetup.newResourceSet();
        Resource resource = new RsamlResource(URI.createFileURI(output.toAbsolutePath().toString()));
        resourceSet.getResources().add(resource);
        resource.getContents().add(EcoreUtil.copy(architecture));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        resource.save(bytes, Map.of(XMLResource.OPTION_ENCODING, "UTF-8"));
        return bytes.toString(StandardCharsets.UTF_8);
    }
}
