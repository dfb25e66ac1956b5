/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.resource;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Iterator;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.linking.lazy.LazyLinkingResource;
import org.eclipse.xtext.resource.XtextSyntaxDiagnostic;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.util.LineAndColumn;
import org.eclipse.xtext.util.OnChangeEvictingCache;
import org.rsaml.model.Architecture;
import org.rsaml.model.resource.LoadProblem;
import org.rsaml.model.resource.LocatingResource;
import org.rsaml.model.resource.ModelFormats;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.SourceLocation;
import org.rsaml.text.grammar.RsamlTextSyntaxErrors;
import org.rsaml.text.serializer.RsamlTextWriter;

import com.google.inject.Inject;

/**
 * The resource of textual {@code .rsa} files. It reads as {@link RsamlResource} reads XMI: regular
 * local files of bounded size only ({@link RsamlResource#OPTION_MAX_FILE_SIZE}), nesting of at most
 * {@link RsamlResource#MAX_DEPTH} levels, references only within the file; every problem is an error
 * in {@link #getErrors()} with its line and column. Each element is located where its keyword is
 * written. Saving writes the canonical text ({@link RsamlTextWriter}).
 */
public class RsamlTextResource extends LazyLinkingResource implements LocatingResource {

    @Inject
    private RsamlTextWriter writer;

    @Override
    public void load(Map<?, ?> options) throws IOException {
        if (!isLoaded()) {
            ModelFormats.refuseUnopenable(this, options);
        }
        super.load(options);
    }

    @Override
    protected void doLoad(InputStream inputStream, Map<?, ?> options) throws IOException {
        byte[] bytes = inputStream.readAllBytes();
        LoadProblem tooDeep = tooDeep(new String(bytes, StandardCharsets.UTF_8));
        if (tooDeep != null) {
            getErrors().add(tooDeep);
            return;
        }
        try {
            super.doLoad(new ByteArrayInputStream(bytes), options);
            EcoreUtil2.resolveLazyCrossReferences(this, CancelIndicator.NullImpl);
        } catch (StackOverflowError e) {
            getContents().clear();
            getErrors().add(new LoadProblem("the model is nested too deeply to be read; RsaML reads at most "
                    + RsamlResource.MAX_DEPTH + " levels", String.valueOf(getURI()), 0, 0));
        }
    }

    /**
     * Resolves every reference with the scopes computed once: resolving one changes nothing a name depends on, so
     * the scope cache is kept (Xtext would clear it at each resolution, which makes linking quadratic in the model).
     */
    @Override
    public void resolveLazyCrossReferences(CancelIndicator monitor) {
        if (getCache() instanceof OnChangeEvictingCache cache) {
            cache.execWithoutCacheClear(this, resource -> {
                super.resolveLazyCrossReferences(monitor);
                return null;
            });
        } else {
            super.resolveLazyCrossReferences(monitor);
        }
    }

    /** Refuses text nested deeper than {@link RsamlResource#MAX_DEPTH} braces before the parser recurses into it. */
    private LoadProblem tooDeep(String text) {
        int depth = 0;
        int line = 1;
        int column = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            column++;
            if (c == '\n') {
                line++;
                column = 0;
            } else if (c == '"') {
                for (i++; i < text.length() && text.charAt(i) != '"' && text.charAt(i) != '\n'; i++) {
                    column++;
                    if (text.charAt(i) == '\\') {
                        i++;
                        column++;
                    }
                }
                column++;
            } else if (c == '/' && i + 1 < text.length() && text.charAt(i + 1) == '/') {
                while (i + 1 < text.length() && text.charAt(i + 1) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < text.length() && text.charAt(i + 1) == '*') {
                int end = text.indexOf("*/", i + 2);
                int stop = end < 0 ? text.length() : end + 2;
                for (int j = i; j < stop; j++) {
                    if (text.charAt(j) == '\n') {
                        line++;
                        column = 0;
                    } else {
                        column++;
                    }
                }
                i = stop - 1;
            } else if (c == '{' && ++depth > RsamlResource.MAX_DEPTH) {
                return new LoadProblem("elements are nested more than " + RsamlResource.MAX_DEPTH
                        + " levels deep; RsaML reads at most that many", String.valueOf(getURI()), line, column);
            } else if (c == '}') {
                depth--;
            }
        }
        return null;
    }

    /** The parser's errors, without those about braces that only follow from an earlier one. */
    @Override
    protected void addSyntaxErrors() {
        super.addSyntaxErrors();
        boolean earlier = false;
        for (Iterator<Diagnostic> it = getErrors().iterator(); it.hasNext();) {
            if (it.next() instanceof XtextSyntaxDiagnostic syntax) {
                if (earlier && RsamlTextSyntaxErrors.UNBALANCED.equals(syntax.getCode())) {
                    it.remove();
                }
                earlier = true;
            }
        }
    }

    @Override
    public void doSave(OutputStream outputStream, Map<?, ?> options) throws IOException {
        if (getContents().isEmpty() || !(getContents().get(0) instanceof Architecture architecture)) {
            throw new IOException("a textual RsaML model holds one architecture; this resource holds "
                    + (getContents().isEmpty() ? "nothing" : "a " + getContents().get(0).eClass().getName()));
        }
        outputStream.write(writer.write(architecture).getBytes(StandardCharsets.UTF_8));
    }

    @Override
    public SourceLocation locate(EObject element) {
        String file = getURI() == null ? "" : getURI().isFile() ? getURI().toFileString() : getURI().toString();
        ICompositeNode node = element.eResource() == this ? NodeModelUtils.getNode(element) : null;
        if (node == null) {
            return new SourceLocation(file, 0, 0);
        }
        LineAndColumn at = NodeModelUtils.getLineAndColumn(node, node.getOffset());
        return new SourceLocation(file, at.getLine(), at.getColumn());
    }

    @Override
    public int locatedElementCount() {
        int count = 0;
        for (var it = getAllContents(); it.hasNext();) {
            if (NodeModelUtils.getNode(it.next()) != null) {
                count++;
            }
        }
        return count;
    }
}
