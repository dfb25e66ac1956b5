/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.XMLConstants;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.common.util.WrappedException;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.ClassNotFoundException;
import org.eclipse.emf.ecore.xmi.FeatureNotFoundException;
import org.eclipse.emf.ecore.xmi.IllegalValueException;
import org.eclipse.emf.ecore.xmi.PackageNotFoundException;
import org.eclipse.emf.ecore.xmi.UnresolvedReferenceException;
import org.eclipse.emf.ecore.xmi.XMIException;
import org.eclipse.emf.ecore.xmi.XMLLoad;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.ecore.xmi.impl.SAXXMIHandler;
import org.eclipse.emf.ecore.xmi.impl.XMILoadImpl;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.util.RsamlResourceImpl;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Reads .rsaml files for validation: safely (no DTDs, no external entities), recording where each
 * element is, and turning every way a file can be unfit into one clear {@link ModelLoadException}.
 */
public final class ModelLoader {

    private ModelLoader() {
    }

    /** Loads {@code path}, reporting it as {@code displayName} in messages. */
    public static LoadedModel load(Path path, String displayName) throws ModelLoadException {
        RsamlValidationSetup.registerPackage();
        byte[] bytes = readChecked(path, displayName);
        ResourceSet resourceSet = new ResourceSetImpl();
        resourceSet.getPackageRegistry().put(RsamlPackage.eNS_URI, RsamlPackage.eINSTANCE);
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("*", (Resource.Factory) LocatingResource::new);
        LocatingResource resource = new LocatingResource(URI.createFileURI(path.toAbsolutePath().toString()));
        resourceSet.getResources().add(resource);
        try {
            resource.load(new ByteArrayInputStream(bytes), loadOptions());
        } catch (IOException | WrappedException e) {
            throw describe(displayName, resource, e);
        } catch (OutOfMemoryError e) {
            resource.unload();
            throw new ModelLoadException(displayName, 0, 0, "the model is too large for the available heap ("
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB); give the JVM more memory with -Xmx (for the rsaml command: RSAML_JAVA_OPTS=-Xmx4g)", null);
        }
        if (!resource.getErrors().isEmpty()) {
            throw describe(displayName, resource, null);
        }
        if (resource.getContents().isEmpty()) {
            throw new ModelLoadException(displayName, "the file holds no model element; an RsaML model has an rsaml:Architecture root");
        }
        EObject root = resource.getContents().get(0);
        if (!(root instanceof Architecture)) {
            int[] at = position(resource, root);
            throw new ModelLoadException(displayName, at[0], at[1], "the root element is a " + root.eClass().getName()
                    + "; an RsaML model's root is an rsaml:Architecture", null);
        }
        checkCrossReferences(displayName, resource);
        return new LoadedModel(resource, displayName, path, resource.elementPositions);
    }

    private static byte[] readChecked(Path path, String file) throws ModelLoadException {
        byte[] bytes;
        try {
            if (Files.isDirectory(path)) {
                throw new ModelLoadException(file, "is a directory, not an .rsaml file");
            }
            bytes = Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new ModelLoadException(file, "no such file");
        } catch (AccessDeniedException e) {
            throw new ModelLoadException(file, "the file cannot be read (permission denied)");
        } catch (IOException e) {
            throw new ModelLoadException(file, 0, 0, "the file cannot be read: " + e.getMessage(), e);
        } catch (OutOfMemoryError e) {
            throw new ModelLoadException(file, "the model is too large for the available heap ("
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB); give the JVM more memory with -Xmx (for the rsaml command: RSAML_JAVA_OPTS=-Xmx4g)");
        }
        if (bytes.length == 0 || new String(bytes, StandardCharsets.UTF_8).isBlank()) {
            throw new ModelLoadException(file, "the file is empty; an RsaML model is an XMI document with an rsaml:Architecture root");
        }
        int scan = Math.min(bytes.length, 8192);
        for (int i = 0; i < scan; i++) {
            if (bytes[i] == 0) {
                throw new ModelLoadException(file, "the file is binary, not an XML model (NUL byte at offset " + i + ")");
            }
        }
        try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(java.nio.ByteBuffer.wrap(bytes, 0, scan));
        } catch (CharacterCodingException e) {
            if (scan == bytes.length || !(e instanceof java.nio.charset.MalformedInputException m) || m.getInputLength() < 4) {
                throw new ModelLoadException(file, "the file is not UTF-8 text; .rsaml files are UTF-8 XML");
            }
        }
        return bytes;
    }

    private static Map<Object, Object> loadOptions() {
        Map<Object, Object> options = new HashMap<>();
        Map<String, Boolean> features = new HashMap<>();
        // Models are data, never code: no DTD, no external or expanding entities.
        features.put("http://apache.org/xml/features/disallow-doctype-decl", Boolean.TRUE);
        features.put("http://xml.org/sax/features/external-general-entities", Boolean.FALSE);
        features.put("http://xml.org/sax/features/external-parameter-entities", Boolean.FALSE);
        features.put("http://apache.org/xml/features/nonvalidating/load-external-dtd", Boolean.FALSE);
        features.put(XMLConstants.FEATURE_SECURE_PROCESSING, Boolean.TRUE);
        options.put(XMLResource.OPTION_PARSER_FEATURES, features);
        options.put(XMLResource.OPTION_USE_PARSER_POOL, null);
        options.put(XMLResource.OPTION_DEFER_IDREF_RESOLUTION, Boolean.TRUE);
        return options;
    }

    private static ModelLoadException describe(String file, Resource resource, Exception thrown) {
        Resource.Diagnostic first = resource.getErrors().isEmpty() ? null : resource.getErrors().get(0);
        Throwable cause = first instanceof Throwable t ? t : thrown;
        while (cause instanceof WrappedException || (cause instanceof IOException && cause.getCause() != null
                && !(cause instanceof XMIException))) {
            cause = cause.getCause();
        }
        if (cause instanceof XMIException && cause.getCause() instanceof SAXParseException sax) {
            cause = sax;
        }
        int line = first != null ? first.getLine() : 0;
        int column = first != null ? first.getColumn() : 0;
        String message;
        if (cause instanceof SAXParseException sax) {
            line = sax.getLineNumber();
            column = sax.getColumnNumber();
            String detail = sax.getMessage();
            message = detail != null && detail.contains("DOCTYPE")
                    ? "DOCTYPE declarations are not allowed in .rsaml files (DTDs and external entities are never loaded)"
                    : "malformed XML: " + detail;
        } else if (cause instanceof PackageNotFoundException p) {
            message = "namespace '" + p.uri() + "' is not RsaML's (" + RsamlPackage.eNS_URI + "); this is not an RsaML model";
        } else if (cause instanceof ClassNotFoundException c) {
            message = "element type '" + c.getName() + "' is not an RsaML concept"
                    + (line <= 2 ? "; this does not look like an RsaML model (root should be rsaml:Architecture)" : "");
        } else if (cause instanceof FeatureNotFoundException f) {
            message = "'" + f.getName() + "' is not a feature of " + (f.getObject() == null ? "this element" : f.getObject().eClass().getName());
        } else if (cause instanceof UnresolvedReferenceException u) {
            message = "reference " + u.getFeature().getName() + " points to '" + u.getReference() + "', which does not exist";
        } else if (cause instanceof IllegalValueException v) {
            message = "illegal value for " + v.getFeature().getName() + ": " + describeValue(v.getValue());
        } else if (cause instanceof XMIException x) {
            message = x.getMessage();
        } else if (cause instanceof RuntimeException && cause.getMessage() != null && cause.getMessage().contains("not a valid")) {
            message = cause.getMessage();
        } else {
            message = "the file cannot be read as an RsaML model: " + (cause == null ? "unknown error" : cause.getMessage());
        }
        int more = Math.max(0, resource.getErrors().size() - 1);
        if (more > 0) {
            message += " (and " + more + " more error" + (more > 1 ? "s" : "") + ")";
        }
        return new ModelLoadException(file, line, column, message, cause);
    }

    private static String describeValue(Object value) {
        return value instanceof EObject o ? "a " + o.eClass().getName() : "'" + value + "'";
    }

    private static void checkCrossReferences(String file, LocatingResource resource) throws ModelLoadException {
        Map<EObject, java.util.Collection<org.eclipse.emf.ecore.EStructuralFeature.Setting>> unresolved =
                EcoreUtil.UnresolvedProxyCrossReferencer.find(resource);
        if (!unresolved.isEmpty()) {
            Map.Entry<EObject, java.util.Collection<org.eclipse.emf.ecore.EStructuralFeature.Setting>> first =
                    unresolved.entrySet().iterator().next();
            org.eclipse.emf.ecore.EStructuralFeature.Setting setting = first.getValue().iterator().next();
            int[] at = position(resource, setting.getEObject());
            throw new ModelLoadException(file, at[0], at[1], "reference " + setting.getEStructuralFeature().getName()
                    + " points to '" + ((InternalEObject) first.getKey()).eProxyURI() + "', which cannot be loaded"
                    + (unresolved.size() > 1 ? " (and " + (unresolved.size() - 1) + " more unresolved references)" : ""), null);
        }
    }

    private static int[] position(LocatingResource resource, EObject object) {
        Long p = resource.elementPositions.get(object);
        return p == null ? new int[] { 0, 0 } : new int[] { (int) (p >>> 32), (int) (long) p };
    }

    /** The RsaML resource, remembering where the parser met each element. */
    static final class LocatingResource extends RsamlResourceImpl {
        final Map<EObject, Long> elementPositions = new IdentityHashMap<>();
        /**
         * Children by their name-keyed fragment segment ({@code @modules[name='m1']}), per container:
         * EMF resolves such a segment by scanning the siblings, which makes loading quadratic in the
         * size of a layer. Only lookups use it; a miss falls back to EMF.
         */
        private final Map<EObject, Index> childrenBySegment = new IdentityHashMap<>();

        /** A container's children by segment, as of when it held {@code size} children. */
        private record Index(int size, Map<String, EObject> children) {
        }

        LocatingResource(URI uri) {
            super(uri);
        }

        @Override
        protected EObject getEObject(List<String> uriFragmentPath) {
            int size = uriFragmentPath.size();
            EObject eObject = getEObjectForURIFragmentRootSegment(size == 0 ? "" : uriFragmentPath.get(0));
            for (int i = 1; i < size && eObject != null; ++i) {
                String segment = uriFragmentPath.get(i);
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

        private static Index index(EObject container) {
            Map<String, EObject> children = new HashMap<>();
            InternalEObject internal = (InternalEObject) container;
            List<EObject> contents = container.eContents();
            for (EObject child : contents) {
                children.putIfAbsent(internal.eURIFragmentSegment(child.eContainingFeature(), child), child);
            }
            return new Index(contents.size(), children);
        }

        @Override
        public void doLoad(java.io.InputStream inputStream, Map<?, ?> options) throws IOException {
            try {
                super.doLoad(inputStream, options);
            } finally {
                // Later edits would make the index stale; it has served its purpose.
                childrenBySegment.clear();
            }
        }

        @Override
        protected XMLLoad createXMLLoad() {
            return new XMILoadImpl(createXMLHelper()) {
                @Override
                protected DefaultHandler makeDefaultHandler() {
                    return new SAXXMIHandler(resource, helper, options) {
                        @Override
                        protected void processObject(EObject object) {
                            if (object != null && locator != null) {
                                elementPositions.put(object, ((long) locator.getLineNumber() << 32) | (locator.getColumnNumber() & 0xffffffffL));
                            }
                            super.processObject(object);
                        }
                    };
                }
            };
        }
    }
}
