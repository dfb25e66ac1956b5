/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.IOException;
import java.io.InputStream;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.XMLConstants;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.xmi.XMLLoad;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.ecore.xmi.XMLSave;
import org.eclipse.emf.ecore.xmi.impl.XMILoadImpl;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.Interruptions;
import org.rsaml.model.util.RsamlResourceImpl;
import org.xml.sax.helpers.DefaultHandler;

/**
 * The resource of {@code .rsaml} files, registered for every EMF client (the tree editor, Sirius,
 * the validator, user code). It reads a file as data, never as code: no DTD, no entity, nothing
 * opened but regular local files of bounded size, references only to {@code .rsaml} files in the
 * referencing file's folder or below it, and namespaces only from the package registry. Every way
 * a file can be unfit becomes one error in {@link #getErrors()} saying what is wrong and, where
 * the parser knows it, the line and column. It remembers where each element's start tag begins,
 * and the file's comments, which a save writes back where they stood.
 */
public class RsamlResource extends RsamlResourceImpl implements LocatingResource {

    /** Load option: the largest file, in bytes, that is read (a {@link Long}). */
    public static final String OPTION_MAX_FILE_SIZE = "org.rsaml.model.resource.maxFileSize";

    /**
     * Load option: the addresses whose text an editor holds (a {@code java.util.function.Predicate} of
     * {@link org.eclipse.emf.common.util.URI}), read from the editor and not opened, so not subject to the loading
     * policy (an unsaved document, {@code untitled:Untitled-1}, or a file the editor has not saved yet).
     */
    public static final String OPTION_EDITOR_TEXT = "org.rsaml.model.resource.editorText";

    /** Files larger than this (1 GiB) are refused unless {@link #OPTION_MAX_FILE_SIZE} says otherwise. */
    public static final long DEFAULT_MAX_FILE_SIZE = 1L << 30;

    /** Elements nested deeper than this are refused (a model's natural depth is below ten). */
    public static final int MAX_DEPTH = 1000;

    /** The fragment given to references that were refused: it names nothing, so nothing is ever opened for them. */
    static final String REFUSED_FRAGMENT = "rsaml-refused-reference";

    /** The file's comments, anchored to elements, written back on save. */
    private final Comments comments = new Comments();

    /** Where each element's start tag begins: line in the high half, column in the low half. */
    private final Map<EObject, Long> positions = new IdentityHashMap<>();

    /**
     * Children by their name-keyed fragment segment ({@code @modules[name='m1']}), per container,
     * while loading: EMF resolves such a segment by scanning the siblings, which makes loading
     * quadratic in the size of a layer. A miss falls back to EMF.
     */
    private final Map<EObject, Index> childrenBySegment = new IdentityHashMap<>();

    /** A container's children by segment, as of when it held {@code size} children. */
    private record Index(int size, Map<String, EObject> children) {
    }

    public RsamlResource(URI uri) {
        super(uri);
    }

    /**
     * Where the element's start tag begins in this resource's file; line and column are 0 for an
     * element that was not read from it.
     */
    @Override
    public SourceLocation locate(EObject element) {
        Long packed = positions.get(element);
        String file = getURI() == null ? "" : getURI().isFile() ? getURI().toFileString() : getURI().toString();
        return packed == null ? new SourceLocation(file, 0, 0)
                : new SourceLocation(file, (int) (packed >>> 32), (int) (long) packed);
    }

    /** How many elements were read from the file (and so have a location). */
    @Override
    public int locatedElementCount() {
        return positions.size();
    }

    /** How many of the file's comments are kept to be written back by a save. */
    public int keptCommentCount() {
        return comments.size();
    }

    Comments comments() {
        return comments;
    }

    /**
     * Reads the element positions again from the file as it is now (after a save, say), matching
     * elements by URI fragment; elements the file does not hold (yet) have none. Contents, comments
     * and errors stay as they are. Does nothing when the file cannot be read as a model.
     */
    public void refreshLocations() {
        RsamlResource current = new RsamlResource(getURI());
        ResourceSetImpl reader = new ResourceSetImpl();
        reader.setURIConverter(getURIConverter()); // platform:/resource/... is read as this resource is
        reader.getResources().add(current);
        try {
            current.load(getResourceSet() == null ? null : getResourceSet().getLoadOptions());
        } catch (IOException | RuntimeException e) {
            return; // the positions of the last successful read stay
        }
        positions.clear();
        for (java.util.Iterator<EObject> it = current.getAllContents(); it.hasNext();) {
            EObject there = it.next();
            Long packed = current.positions.get(there);
            EObject here = packed == null ? null : getEObject(current.getURIFragment(there));
            if (here != null) {
                positions.put(here, packed);
            }
        }
    }

    void recordPosition(EObject element, int line, int column) {
        positions.put(element, ((long) line << 32) | (column & 0xffffffffL));
    }

    @Override
    public void load(Map<?, ?> options) throws IOException {
        if (!isLoaded()) {
            ModelFormats.refuseUnopenable(this, options);
        }
        super.load(options);
    }

    @Override
    public void doLoad(InputStream inputStream, Map<?, ?> options) throws IOException {
        positions.clear();
        comments.clear();
        PrologRecorder prolog = new PrologRecorder(inputStream);
        LocatingHandler.Context context = new LocatingHandler.Context(prolog);
        try {
            super.doLoad(prolog, hardened(options, context));
        } catch (IOException | RuntimeException e) {
            if (getErrors().isEmpty()) {
                getErrors().add(LoadMessages.unexpected(e, getURI(), context));
            }
        } catch (OutOfMemoryError e) {
            getContents().clear();
            comments.clear();
            positions.clear();
            getErrors().clear();
            getErrors().add(new LoadProblem("the model is too large for the available heap ("
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB); give the Java virtual machine more memory (-Xmx)",
                    String.valueOf(getURI()), 0, 0));
        } finally {
            // Later edits would make the index stale; it has served its purpose.
            childrenBySegment.clear();
        }
        if (context.encoding != null) {
            setEncoding(context.encoding);
        }
        if (getErrors().isEmpty()) {
            checkRoot();
        }
        if (!getErrors().isEmpty()) {
            throw new IOWrappedException((Exception) getErrors().get(0));
        }
    }

    private void checkRoot() {
        if (getContents().isEmpty()) {
            getErrors().add(new LoadProblem("the file holds no model element; an RsaML model has an rsaml:Architecture root",
                    String.valueOf(getURI()), 0, 0));
            return;
        }
        EObject root = getContents().get(0);
        if (!(root instanceof Architecture)) {
            SourceLocation at = locate(root);
            getErrors().add(new LoadProblem("the root element is a " + root.eClass().getName()
                    + "; an RsaML model's root is an rsaml:Architecture", String.valueOf(getURI()), at.line(), at.column()));
        }
    }

    /** The caller's options with RsaML's safety settings forced on top. */
    private static Map<Object, Object> hardened(Map<?, ?> options, LocatingHandler.Context context) {
        Map<Object, Object> result = options == null ? new HashMap<>() : new HashMap<>(options);
        Map<String, Boolean> features = new HashMap<>();
        if (result.get(XMLResource.OPTION_PARSER_FEATURES) instanceof Map<?, ?> given) {
            given.forEach((k, v) -> features.put(String.valueOf(k), (Boolean) v));
        }
        // Models are data, never code: no DTD, no external or expanding entities.
        features.put("http://apache.org/xml/features/disallow-doctype-decl", Boolean.TRUE);
        features.put("http://xml.org/sax/features/external-general-entities", Boolean.FALSE);
        features.put("http://xml.org/sax/features/external-parameter-entities", Boolean.FALSE);
        features.put("http://apache.org/xml/features/nonvalidating/load-external-dtd", Boolean.FALSE);
        features.put(XMLConstants.FEATURE_SECURE_PROCESSING, Boolean.TRUE);
        result.put(XMLResource.OPTION_PARSER_FEATURES, features);
        // RsaML refuses nesting beyond MAX_DEPTH itself, naming the line; the JDK's own limit (100 levels in Java
        // 24's jaxp.properties, none before) stays above it as a backstop, so that every Java reads the same models.
        result.put(XMLResource.OPTION_PARSER_PROPERTIES,
                Map.of("http://www.oracle.com/xml/jaxp/properties/maxElementDepth", String.valueOf(2 * MAX_DEPTH)));
        result.remove(XMLResource.OPTION_USE_PARSER_POOL);
        result.remove(XMLResource.OPTION_USE_DEPRECATED_METHODS);
        result.remove(XMLResource.OPTION_EXTENDED_META_DATA);
        result.remove(XMLResource.OPTION_RECORD_UNKNOWN_FEATURE);
        result.remove(XMLResource.OPTION_PROCESS_DANGLING_HREF);
        result.put(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE);
        // Comments are reported too, so that every piece of markup moves the position forward.
        result.put(XMLResource.OPTION_USE_LEXICAL_HANDLER, Boolean.TRUE);
        result.put(LocatingHandler.Context.class, context);
        return result;
    }

    /** EMF's XMI save, which also writes back the comments the file had when it was read. */
    @Override
    protected XMLSave createXMLSave() {
        return new CommentKeepingSave(createXMLHelper(), comments);
    }

    @Override
    protected XMLLoad createXMLLoad() {
        return new XMILoadImpl(createXMLHelper()) {
            @Override
            protected DefaultHandler makeDefaultHandler() {
                return new LocatingHandler(RsamlResource.this, helper, options,
                        (LocatingHandler.Context) options.get(LocatingHandler.Context.class));
            }

            @Override
            @SuppressWarnings("deprecation")
            protected String getEncoding() throws IOException {
                try {
                    return super.getEncoding();
                } catch (IndexOutOfBoundsException e) {
                    // EMF's quick scan of the XML declaration fails on an unterminated encoding="...; the
                    // parser reports the same declaration as a located error, so let it read the file.
                    return null;
                }
            }
        };
    }

    @Override
    public EObject getEObject(String uriFragment) {
        return REFUSED_FRAGMENT.equals(uriFragment) ? null : super.getEObject(uriFragment);
    }

    @Override
    protected EObject getEObject(List<String> uriFragmentPath) {
        Interruptions.check();
        int size = uriFragmentPath.size();
        EObject eObject = getEObjectForURIFragmentRootSegment(size == 0 ? "" : uriFragmentPath.get(0));
        for (int i = 1; i < size && eObject != null; ++i) {
            String segment = uriFragmentPath.get(i);
            if (!isLoading()) {
                eObject = ((InternalEObject) eObject).eObjectForURIFragmentSegment(segment);
                continue;
            }
            if (segment.indexOf('[') < 0) {
                // Positional segments (@connections.12) are a direct list access already.
                eObject = ((InternalEObject) eObject).eObjectForURIFragmentSegment(segment);
                continue;
            }
            EObject container = eObject;
            Index index = childrenBySegment.get(container);
            EObject child = index == null ? null : index.children().get(segment);
            if (child == null && (index == null || index.size() != container.eContents().size())) {
                // Children were added since (references resolved while loading): index again.
                index = index(container);
                childrenBySegment.put(container, index);
                child = index.children().get(segment);
            }
            eObject = child != null ? child : ((InternalEObject) container).eObjectForURIFragmentSegment(segment);
        }
        return eObject;
    }

    /** The children of the container's keyed lists ({@code eKeys}, such as name), by segment. */
    @SuppressWarnings("unchecked")
    private static Index index(EObject container) {
        Map<String, EObject> children = new HashMap<>();
        InternalEObject internal = (InternalEObject) container;
        for (EReference containment : container.eClass().getEAllContainments()) {
            if (containment.isMany() && !containment.getEKeys().isEmpty()) {
                for (EObject child : (List<EObject>) container.eGet(containment, false)) {
                    children.putIfAbsent(internal.eURIFragmentSegment(containment, child), child);
                }
            }
        }
        return new Index(container.eContents().size(), children);
    }

    @Override
    protected void doUnload() {
        positions.clear();
        comments.clear();
        childrenBySegment.clear();
        super.doUnload();
    }
}
