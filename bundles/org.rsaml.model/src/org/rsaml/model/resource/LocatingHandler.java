/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.Map;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.xmi.ClassNotFoundException;
import org.eclipse.emf.ecore.xmi.PackageNotFoundException;
import org.eclipse.emf.ecore.xmi.UnresolvedReferenceException;
import org.eclipse.emf.ecore.xmi.XMIException;
import org.eclipse.emf.ecore.xmi.XMLHelper;
import org.eclipse.emf.ecore.xmi.impl.SAXXMIHandler;
import org.rsaml.model.support.Interruptions;
import org.xml.sax.Attributes;
import org.xml.sax.SAXException;
import org.xml.sax.ext.Locator2;

/**
 * EMF's XMI handler, made to read untrusted files: namespaces come only from the package registry
 * (nothing is downloaded), references are checked before they become proxies, non-finite numbers
 * are refused, and every error is rewritten as a sentence. It also records where each element's
 * start tag begins, from the parser's own positions (no second reading of the file): a tag starts
 * where the markup or text before it ended, so lines are counted exactly as the parser counts
 * them (CR, CRLF, LF, and NEL and LS in XML 1.1), in whatever encoding it read.
 */
final class LocatingHandler extends SAXXMIHandler {

    /** What the handler learns about the file, kept for the resource to describe errors. */
    static final class Context {
        final PrologRecorder prolog;
        boolean rootSeen;
        String encoding;

        Context(PrologRecorder prolog) {
            this.prolog = prolog;
        }
    }

    private final RsamlResource rsamlResource;
    private final Context context;
    /** Where the markup last reported by the parser ended. */
    private int lastLine = 1;
    private int lastColumn = 1;
    /**
     * Where text since the last markup ends, counted through the characters the parser delivered
     * (line ends arrive as one '\n' each, whatever they were in the file); -1 when there was none.
     */
    private int textLine = -1;
    private int textColumn;
    /** Whether the count agrees with the parser's position at each piece of text. */
    private boolean textReliable;
    /** Where the start tag being handled begins. */
    private int tagLine;
    private int tagColumn;
    private boolean inStartTag;
    private int depth;
    private int elements;
    /** The element being started, and the xsi:type being created with the feature it is for: to name them in errors. */
    private String elementName;
    private String typeName;
    private EStructuralFeature typedFeature;
    /** A namespace was already reported as unknown: its elements' types cannot be found either, which says nothing new. */
    private boolean unknownNamespace;
    /** The attributes of the start tag being handled. */
    private Attributes tagAttributes;
    /** Comments read since the last start or end tag, waiting for the element they stand before. */
    private final List<String> pendingComments = new ArrayList<>();
    /** The model element each open XML element created (empty for an element that is a feature's value, say). */
    private final Deque<Optional<EObject>> openElements = new ArrayDeque<>();
    /** The element the start tag being handled created. */
    private EObject created;
    /** Elements that could not be created because they do not say which kind they are, in the order of the file. */
    private final List<Untyped> untyped = new ArrayList<>();

    /**
     * An element without a concrete type: its error, and the references to it, which cannot resolve
     * while it is missing and are counted in its error instead of each being reported as dangling.
     */
    private static final class Untyped {
        final EObject container;
        final String segment;
        final LoadProblem problem;
        final List<Integer> referencedFrom = new ArrayList<>();

        Untyped(EObject container, String segment, LoadProblem problem) {
            this.container = container;
            this.segment = segment;
            this.problem = problem;
        }
    }

    LocatingHandler(RsamlResource resource, XMLHelper helper, Map<?, ?> options, Context context) {
        super(resource, helper, options);
        this.rsamlResource = resource;
        this.context = context;
    }

    private void mark() {
        textLine = -1;
        if (locator != null) {
            lastLine = locator.getLineNumber();
            lastColumn = locator.getColumnNumber();
        }
    }

    @Override
    public void startElement(String uri, String localName, String name, Attributes attributes) throws SAXException {
        if (!context.rootSeen) {
            context.rootSeen = true;
            if (locator instanceof Locator2 l) {
                context.encoding = l.getEncoding();
            }
            locateRoot();
            context.prolog.stop();
        } else {
            tagStartAfterText();
        }
        if (++depth > RsamlResource.MAX_DEPTH) {
            // EMF attaches each element by walking up to the root: deeper nesting would cost its square.
            error(new LoadProblem("elements are nested more than " + RsamlResource.MAX_DEPTH
                    + " levels deep here; RsaML reads models up to that depth", getLocation(), tagLine, tagColumn));
            throw new SAXException("nested too deep");
        }
        Interruptions.check();
        if ((++elements & 0xfff) == 0 && HeapWatch.nearlyExhausted()) {
            // Give up now, as the JVM would later, instead of letting the collector thrash for minutes first.
            throw new OutOfMemoryError("the heap is nearly full right after a collection");
        }
        inStartTag = true;
        elementName = name;
        tagAttributes = attributes;
        created = null;
        try {
            super.startElement(uri, localName, name, attributes);
        } finally {
            inStartTag = false;
            tagAttributes = null;
            mark();
        }
        if (created != null && !pendingComments.isEmpty()) {
            rsamlResource.comments().addBefore(created, pendingComments);
            pendingComments.clear();
        }
        openElements.push(Optional.ofNullable(created));
    }

    /**
     * After markup, the tag starts where the markup ended. After text, it starts where the text
     * ends; the parser's own position there may already be past the '&lt;' (it has read it to end
     * the text), so the delivered text is counted unless it holds references ({@code &amp;amp;}),
     * whose characters are fewer than the file's.
     */
    private void tagStartAfterText() {
        if (textLine < 0) {
            tagLine = lastLine;
            tagColumn = lastColumn;
        } else if (textReliable) {
            tagLine = textLine;
            tagColumn = textColumn;
        } else {
            // References in the text: the parser's position, which has read the '<'.
            tagLine = lastLine;
            tagColumn = Math.max(1, lastColumn - 1);
        }
    }

    /**
     * The parser reports nothing for the XML declaration or for white space before the root, so
     * the root's start tag is found in the bytes read so far ({@link PrologRecorder#rootTagStart}).
     */
    private void locateRoot() {
        tagLine = locator == null ? 0 : locator.getLineNumber();
        tagColumn = locator == null ? 0 : locator.getColumnNumber();
        String version = locator instanceof Locator2 l ? l.getXMLVersion() : "1.0";
        int[] start = context.prolog.rootTagStart(context.encoding, "1.1".equals(version));
        if (start != null) {
            tagLine = start[0];
            tagColumn = start[1];
        }
    }

    private void countText(char[] ch, int start, int length) {
        if (textLine < 0) {
            textLine = lastLine;
            textColumn = lastColumn;
            textReliable = true;
        }
        for (int i = start; i < start + length; i++) {
            if (ch[i] == '\n') {
                textLine++;
                textColumn = 1;
            } else {
                textColumn++;
            }
        }
        if (locator != null) {
            int line = locator.getLineNumber();
            int column = locator.getColumnNumber();
            textReliable &= line == textLine && (column == textColumn || column == textColumn + 1);
            lastLine = line;
            lastColumn = column;
        }
    }

    @Override
    public void endElement(String uri, String localName, String name) {
        depth--;
        super.endElement(uri, localName, name);
        mark();
        Optional<EObject> ended = openElements.isEmpty() ? Optional.empty() : openElements.pop();
        if (ended.isPresent() && !pendingComments.isEmpty()) {
            rsamlResource.comments().addAtEnd(ended.get(), pendingComments);
            pendingComments.clear();
        }
    }

    @Override
    public void characters(char[] ch, int start, int length) {
        countText(ch, start, length);
        super.characters(ch, start, length);
    }

    @Override
    public void ignorableWhitespace(char[] ch, int start, int length) throws SAXException {
        countText(ch, start, length);
        super.ignorableWhitespace(ch, start, length);
    }

    @Override
    public void processingInstruction(String target, String data) {
        mark();
        super.processingInstruction(target, data);
    }

    @Override
    public void comment(char[] ch, int start, int length) {
        mark();
        // Kept for saving: EMF's XMI save writes none of a file's comments otherwise.
        pendingComments.add(new String(ch, start, length));
        super.comment(ch, start, length);
    }

    @Override
    public void startCDATA() {
        mark();
        super.startCDATA();
    }

    @Override
    public void endCDATA() {
        mark();
        super.endCDATA();
    }

    /** Errors found while a start tag is handled point at the tag's start, as findings do. */
    @Override
    protected int getLineNumber() {
        return inStartTag ? tagLine : super.getLineNumber();
    }

    @Override
    protected int getColumnNumber() {
        return inStartTag ? tagColumn : super.getColumnNumber();
    }

    @Override
    protected void processObject(EObject object) {
        if (object != null) {
            rsamlResource.recordPosition(object, tagLine, tagColumn);
            if (inStartTag) {
                created = object;
            }
        }
        super.processObject(object);
    }

    /** Only registered packages: an unknown namespace is an error, never a download. */
    @Override
    protected EPackage getPackageForURI(String uriString) {
        if (uriString == null) {
            return null;
        }
        EPackage ePackage = packageRegistry.getEPackage(uriString);
        if (ePackage != null && ePackage.eIsProxy()) {
            ePackage = null;
        }
        if (ePackage == null) {
            ePackage = handleMissingPackage(uriString);
        }
        if (ePackage == null) {
            error(new PackageNotFoundException(uriString, getLocation(), getLineNumber(), getColumnNumber()));
        }
        return ePackage;
    }

    @Override
    protected void handleXSISchemaLocation(String schemaLocations) {
        // Schema locations are addresses to fetch metamodels from: never followed.
    }

    @Override
    protected void handleXSINoNamespaceSchemaLocation(String noNamespaceSchemaLocation) {
        // as above
    }

    @Override
    protected void processSchemaLocations(String prefix, String name) {
        // as above
    }

    @Override
    protected void handleProxy(InternalEObject proxy, String uriLiteral) {
        if (!uriLiteral.startsWith("#")) {
            String refusal = LoadPolicy.refuseReference(uriLiteral, resourceURI);
            if (refusal != null) {
                error(new LoadProblem(refusal, getLocation(), getLineNumber(), getColumnNumber()));
                proxy.eSetProxyURI(resourceURI == null ? org.eclipse.emf.common.util.URI.createURI("#" + RsamlResource.REFUSED_FRAGMENT)
                        : resourceURI.appendFragment(RsamlResource.REFUSED_FRAGMENT));
                return;
            }
        }
        super.handleProxy(proxy, uriLiteral);
    }

    @Override
    protected void setFeatureValue(EObject object, EStructuralFeature feature, Object value, int position) {
        if (value instanceof String text && feature instanceof EAttribute && LoadMessages.isFloating(feature)) {
            String refusal = LoadMessages.nonFinite(feature, text);
            if (refusal != null) {
                error(new LoadProblem(refusal, getLocation(), getLineNumber(), getColumnNumber()));
                return;
            }
        }
        super.setFeatureValue(object, feature, value, position);
    }

    @Override
    protected EObject createObjectFromTypeName(EObject peekObject, String typeQName, EStructuralFeature feature) {
        typeName = typeQName;
        typedFeature = feature;
        try {
            return super.createObjectFromTypeName(peekObject, typeQName, feature);
        } finally {
            typeName = null;
            typedFeature = null;
        }
    }

    @Override
    public void error(XMIException e) {
        // EMF reports a reference it failed to resolve here and goes on with the next: a stopped command ends instead.
        Interruptions.check();
        if (e instanceof ClassNotFoundException c && c.getFactory() == null && unknownNamespace) {
            return;
        }
        unknownNamespace |= e instanceof PackageNotFoundException;
        if (e instanceof PackageNotFoundException p && p.uri() == null) {
            // EMF names no namespace as 'null': say which element or type lacks one.
            super.error(new LoadProblem(LoadMessages.noNamespace(elementName, typeName, typedFeature), e, getLocation(),
                    e.getLine(), e.getColumn()));
            return;
        }
        if (e instanceof ClassNotFoundException c && inStartTag) {
            String name = tagAttributes == null ? null : tagAttributes.getValue("name");
            String message = LoadMessages.untyped(c, elementName, name);
            if (message != null) {
                LoadProblem problem = new LoadProblem(message, e, getLocation(), e.getLine(), e.getColumn());
                EObject container = objects.peekEObject();
                if (name != null && container != null && !name.contains("'")) {
                    untyped.add(new Untyped(container, "@" + elementName + "[name='" + name + "']", problem));
                }
                super.error(problem);
                return;
            }
        }
        if (e instanceof UnresolvedReferenceException u && toUntyped(u)) {
            return;
        }
        super.error(e instanceof LoadProblem ? e : LoadMessages.describe(e, context, getLocation(), rsamlResource));
    }

    /** Whether the reference points into an element that could not be created for want of a type; counted there if so. */
    private boolean toUntyped(UnresolvedReferenceException u) {
        String reference = u.getReference();
        if (untyped.isEmpty() || reference == null) {
            return false;
        }
        for (Untyped element : untyped) {
            int at = reference.indexOf("/" + element.segment);
            int end = at + 1 + element.segment.length();
            if (at > 0 && (end == reference.length() || reference.charAt(end) == '/')
                    && rsamlResource.getEObject(reference.substring(0, at)) == element.container) {
                int line = u.getLine();
                if (line <= 0 && u.getObject() != null) {
                    line = rsamlResource.locate(u.getObject()).line();
                }
                element.referencedFrom.add(line);
                return true;
            }
        }
        return false;
    }

    @Override
    public void endDocument() {
        super.endDocument();
        rsamlResource.comments().addAfterRoot(pendingComments);
        pendingComments.clear();
        // References are resolved at the end: each untyped element's error now says how many pointed to it.
        List<Resource.Diagnostic> errors = xmlResource.getErrors();
        for (Untyped element : untyped) {
            int index = errors.indexOf(element.problem);
            if (index >= 0 && !element.referencedFrom.isEmpty()) {
                LoadProblem p = element.problem;
                errors.set(index, new LoadProblem(p.getMessage() + LoadMessages.referencesWaiting(element.referencedFrom),
                        (Exception) p.getCause(), p.getLocation(), p.getLine(), p.getColumn()));
            }
        }
    }

    @Override
    public void fatalError(XMIException e) {
        super.fatalError(e instanceof LoadProblem ? e : LoadMessages.describe(e, context, getLocation(), rsamlResource));
    }
}
