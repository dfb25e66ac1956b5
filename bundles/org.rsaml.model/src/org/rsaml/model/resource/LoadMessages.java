/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.CharConversionException;
import java.io.IOException;
import java.io.UnsupportedEncodingException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EEnumLiteral;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.xmi.ClassNotFoundException;
import org.eclipse.emf.ecore.xmi.FeatureNotFoundException;
import org.eclipse.emf.ecore.xmi.IllegalValueException;
import org.eclipse.emf.ecore.xmi.PackageNotFoundException;
import org.eclipse.emf.ecore.xmi.UnresolvedReferenceException;
import org.eclipse.emf.ecore.xmi.XMIException;
import org.rsaml.model.RsamlPackage;
import org.xml.sax.SAXParseException;

/**
 * Turns what EMF and the XML parser report into sentences a modeler can act on. What is legal
 * (types, literals, features, units) is read from the metamodel, never listed by hand.
 */
final class LoadMessages {

    private static final Pattern NUMBER_WITH_UNIT = Pattern.compile("\\s*([-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\\s*([A-Za-zµ]+)\\s*");
    private static final Pattern BAD_UTF8 = Pattern.compile("Invalid byte \\d+ of \\d+-byte UTF-8 sequence\\.?");
    private static final Pattern DECLARED_ENCODING = Pattern.compile("encoding\\s*=\\s*([\"'])(.*?)\\1");
    private static final Pattern BAD_ENCODING = Pattern.compile(".*[Ee]ncoding[^\"]*\"([^\"]*)\".*");

    /** Problems of the whole file, which no line or column would help to find. */
    private static final String BINARY = "the file is binary";
    private static final String EMPTY = "the file is empty";
    private static final String ENCODING = "the XML declaration names the encoding";

    private LoadMessages() {
    }

    static LoadProblem describe(XMIException e, LocatingHandler.Context context, String location, RsamlResource resource) {
        int line = e.getLine();
        int column = e.getColumn();
        if (line <= 0 && e instanceof IllegalValueException v && v.getObject() != null) {
            // References resolved at the end of the document: point at the referring element.
            SourceLocation at = resource.locate(v.getObject());
            line = at.line();
            column = at.column();
        }
        Throwable cause = e.getCause();
        String message;
        if (e instanceof PackageNotFoundException p) {
            message = "namespace '" + p.uri() + "' is not RsaML's (" + RsamlPackage.eNS_URI + "); this is not an RsaML model";
        } else if (e instanceof ClassNotFoundException c) {
            message = unknownClass(c, line);
        } else if (e instanceof FeatureNotFoundException f) {
            message = unknownFeature(f);
        } else if (e instanceof UnresolvedReferenceException u) {
            message = "reference " + u.getFeature().getName() + " points to '" + u.getReference() + "', which does not exist";
        } else if (e instanceof IllegalValueException v) {
            message = illegalValue(v);
        } else if (cause instanceof UnsupportedEncodingException) {
            message = unknownEncoding(cause.getMessage(), context);
        } else if (cause != null) {
            // Reported by the parser (as a SAXParseException, or the decoding exception it wraps).
            message = parseError(cause.getMessage(), context);
        } else {
            message = "the file cannot be read as an RsaML model: " + e.getMessage();
        }
        return placed(message, e, location, line, column);
    }

    /** The problem, at the place that helps: none for the whole file, the XML declaration for its encoding. */
    private static LoadProblem placed(String message, Exception e, String location, int line, int column) {
        if (message.startsWith(BINARY) || message.startsWith(EMPTY)) {
            return new LoadProblem(message, e, location, 0, 0);
        }
        if (message.startsWith(ENCODING) && line <= 0) {
            // The XML declaration opens the file.
            return new LoadProblem(message, e, location, 1, 1);
        }
        return new LoadProblem(message, e, location, line, column);
    }

    /** An exception that escaped EMF's handler, as a problem of the file. */
    static LoadProblem unexpected(Exception e, URI uri, LocatingHandler.Context context) {
        Throwable cause = e;
        while (cause.getCause() != null && cause.getCause() != cause && !(cause instanceof SAXParseException)) {
            cause = cause.getCause();
        }
        if (cause instanceof SAXParseException sax) {
            return placed(parseError(sax.getMessage(), context), e, String.valueOf(uri), sax.getLineNumber(), sax.getColumnNumber());
        }
        if (cause instanceof UnsupportedEncodingException) {
            return placed(unknownEncoding(cause.getMessage(), context), e, String.valueOf(uri), 0, 0);
        }
        if (cause instanceof CharConversionException) {
            return placed(parseError(cause.getMessage(), context), e, String.valueOf(uri), 0, 0);
        }
        String detail = cause.getMessage() == null ? "" : cause.getMessage().replaceAll("\\s+", " ").strip();
        if (uri != null && uri.isFile()) {
            detail = detail.replace(uri.toFileString(), uri.lastSegment());
        }
        if (cause instanceof IOException) {
            return new LoadProblem("the file cannot be read" + (detail.isEmpty() ? "" : " (" + detail + ")"), e, String.valueOf(uri), 0, 0);
        }
        // A fault of RsaML or of a library, not of the file: said so, on this file only.
        return new LoadProblem("RsaML failed on this file with an internal error (" + cause.getClass().getSimpleName()
                + (detail.isEmpty() ? "" : ": " + detail) + "); please report it together with the file", e, String.valueOf(uri), 0, 0);
    }

    /** An element, or the type in its xsi:type, that is in no namespace. */
    static String noNamespace(String element, String type, EStructuralFeature feature) {
        if (type != null) {
            List<String> kinds = feature != null && feature.getEType() instanceof EClass eClass
                    ? concreteSubclasses(eClass).stream().map(k -> "xsi:type=\"rsaml:" + k.getName() + "\"").toList()
                    : List.of();
            return "xsi:type=\"" + type + "\" names a type without RsaML's namespace prefix; write "
                    + (kinds.isEmpty() ? "xsi:type=\"rsaml:" + type + "\"" : or(kinds));
        }
        return "element '" + element + "' is in no namespace, so this is not an RsaML model; an RsaML model's root is"
                + " rsaml:Architecture with xmlns:rsaml=\"" + RsamlPackage.eNS_URI + "\"";
    }

    /** The parser upper-cases the name: the declaration's own spelling is shown when it can be found. */
    private static String unknownEncoding(String parsed, LocatingHandler.Context context) {
        String name = parsed;
        Matcher declared = DECLARED_ENCODING.matcher(new String(context.prolog.bytes(), StandardCharsets.ISO_8859_1));
        if (declared.find() && (parsed == null || declared.group(2).equalsIgnoreCase(parsed))) {
            name = declared.group(2);
        }
        return ENCODING + " '" + name
                + "', which is not known here; save the file as UTF-8 and declare encoding=\"UTF-8\"";
    }

    private static String parseError(String detail, LocatingHandler.Context context) {
        // One line, of a readable length: the parser quotes the file, line breaks and all.
        String text = detail == null ? "" : detail.replaceAll("\\s+", " ").trim();
        if (text.length() > 300) {
            text = text.substring(0, 300) + "...";
        }
        if (text.contains("DOCTYPE")) {
            return "DOCTYPE declarations are not allowed in .rsaml files (DTDs and external entities are never loaded)";
        }
        if (!context.rootSeen) {
            byte[] start = context.prolog.bytes();
            int nul = binaryAt(start);
            if (nul >= 0) {
                return BINARY + ", not an XML model (NUL byte at offset " + nul + ")";
            }
            if (text.startsWith("Premature end of file")) {
                return isBlank(start) ? EMPTY + "; an RsaML model is an XMI document with an rsaml:Architecture root"
                        : "the file ends before its root element; an RsaML model is an XMI document with an rsaml:Architecture root";
            }
        }
        if (BAD_UTF8.matcher(text).matches()) {
            return "the file is not valid UTF-8 text here; save it as UTF-8, or declare its real encoding"
                    + " in the XML declaration (<?xml version=\"1.0\" encoding=\"...\"?>)";
        }
        Matcher encoding = BAD_ENCODING.matcher(text);
        if (encoding.matches() && !context.rootSeen) {
            return unknownEncoding(encoding.group(1), context);
        }
        if (text.contains("UTF-8") || text.contains("UTF-16") || text.startsWith("Invalid byte")) {
            return "the file is not valid text in its encoding (" + (context.encoding == null ? "UTF-8" : context.encoding)
                    + "): " + text + "; save it as UTF-8, or declare its real encoding in the XML declaration";
        }
        if (text.startsWith("XML document structures must start and end within the same entity")) {
            return "the file ends before its elements are closed; it may have been cut short";
        }
        return "malformed XML: " + text;
    }

    /** The offset of a NUL byte in a file that is not UTF-16 or UTF-32 text, or -1. */
    private static int binaryAt(byte[] bytes) {
        int n = Math.min(bytes.length, 8192);
        if (n >= 2 && ((bytes[0] & 0xff) == 0xfe && (bytes[1] & 0xff) == 0xff || (bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xfe)) {
            return -1;
        }
        if (n >= 2 && (bytes[0] == 0 && bytes[1] == '<' || bytes[0] == '<' && bytes[1] == 0)) {
            return -1;
        }
        if (n >= 4 && bytes[0] == 0 && bytes[1] == 0) {
            return -1;
        }
        for (int i = 0; i < n; i++) {
            if (bytes[i] == 0) {
                return i;
            }
        }
        return -1;
    }

    private static boolean isBlank(byte[] bytes) {
        for (int i = 0; i < bytes.length; i++) {
            int b = bytes[i] & 0xff;
            boolean bom = i < 3 && (b == 0xef || b == 0xbb || b == 0xbf || b == 0xfe || b == 0xff);
            if (!(b == ' ' || b == '\t' || b == '\r' || b == '\n' || b == 0 || bom)) {
                return false;
            }
        }
        return true;
    }

    private static String unknownClass(ClassNotFoundException c, int line) {
        EPackage ePackage = c.getFactory() == null ? null : c.getFactory().getEPackage();
        EClassifier classifier = ePackage == null ? null : ePackage.getEClassifier(c.getName());
        if (classifier instanceof EClass eClass && (eClass.isAbstract() || eClass.isInterface())) {
            List<String> kinds = concreteSubclasses(eClass).stream()
                    .map(k -> "xsi:type=\"" + ePackage.getNsPrefix() + ":" + k.getName() + "\"").toList();
            return "a " + eClass.getName() + " must say which kind it is: add " + or(kinds);
        }
        return "element type '" + c.getName() + "' is not an RsaML concept"
                + (line <= 2 ? "; this does not look like an RsaML model (root should be rsaml:Architecture)" : "");
    }

    /**
     * An element whose tag names an abstract type, or none where the feature's type is abstract
     * (a port without xsi:type): which element, and the xsi:type values it can take; {@code null}
     * when the type is not abstract.
     */
    static String untyped(ClassNotFoundException c, String feature, String name) {
        EPackage ePackage = c.getFactory() == null ? null : c.getFactory().getEPackage();
        EClassifier classifier = ePackage == null ? null : ePackage.getEClassifier(c.getName());
        if (!(classifier instanceof EClass eClass && (eClass.isAbstract() || eClass.isInterface()))) {
            return null;
        }
        List<String> kinds = concreteSubclasses(eClass).stream()
                .map(k -> "xsi:type=\"" + ePackage.getNsPrefix() + ":" + k.getName() + "\"").toList();
        String element = "<" + feature + (name == null ? "" : " name=\"" + name + "\"") + ">";
        return element + " does not say which kind of " + eClass.getName() + " it is, so it cannot be read: add " + or(kinds)
                + " to it";
    }

    /** What an untyped element's error adds about the references to it, which are not reported one by one. */
    static String referencesWaiting(List<Integer> lines) {
        List<String> where = lines.stream().distinct().sorted().map(String::valueOf).toList();
        String joined = where.size() == 1 ? where.get(0)
                : String.join(", ", where.subList(0, where.size() - 1)) + " and " + where.get(where.size() - 1);
        return "; " + (lines.size() == 1 ? "the reference to it" : "the " + lines.size() + " references to it") + " (line"
                + (where.size() == 1 ? " " : "s ") + joined + ") will resolve once it has one";
    }

    private static List<EClass> concreteSubclasses(EClass eClass) {
        return eClass.getEPackage().getEClassifiers().stream().filter(EClass.class::isInstance).map(EClass.class::cast)
                .filter(k -> !k.isAbstract() && !k.isInterface() && eClass.isSuperTypeOf(k)).toList();
    }

    private static String or(List<String> items) {
        if (items.size() <= 1) {
            return String.join("", items);
        }
        return String.join(", ", items.subList(0, items.size() - 1)) + " or " + items.get(items.size() - 1);
    }

    private static String unknownFeature(FeatureNotFoundException f) {
        if (f.getObject() == null) {
            return "'" + f.getName() + "' is not a feature of this element";
        }
        EClass eClass = f.getObject().eClass();
        List<String> names = eClass.getEAllStructuralFeatures().stream()
                .filter(x -> !x.isTransient() && !x.isDerived() && x.isChangeable()).map(EStructuralFeature::getName).toList();
        return "'" + f.getName() + "' is not a feature of " + eClass.getName() + "; its features are " + String.join(", ", names);
    }

    private static String illegalValue(IllegalValueException v) {
        EStructuralFeature feature = v.getFeature();
        Object value = v.getValue();
        if (value instanceof EObject o && feature.isMany() && feature.getEType().isInstance(o) && v.getObject() != null
                && v.getObject().eGet(feature) instanceof java.util.List<?> values && values.contains(o)) {
            // EMF refuses a second mention of one element in a reference that holds each element once
            return "reference " + feature.getName() + " names " + label(o) + " twice: name each element once";
        }
        if (value instanceof EObject o) {
            String expected = feature.getEType() instanceof EClass type && (type.isAbstract() || type.isInterface())
                    ? or(concreteSubclasses(type).stream().map(k -> article(k.getName())).toList())
                    : article(feature.getEType().getName());
            if (feature instanceof EReference r && r.isContainment()) {
                return feature.getName() + " holds " + expected + ", not " + article(o.eClass().getName());
            }
            return "reference " + feature.getName() + " must name " + expected + ", but " + label(o) + " is "
                    + article(o.eClass().getName());
        }
        String text = String.valueOf(value);
        EClassifier type = feature.getEType();
        if (type instanceof EEnum eEnum) {
            return "'" + text + "' is not a value of " + feature.getName() + "; write one of "
                    + or(eEnum.getELiterals().stream().map(EEnumLiteral::getLiteral).toList());
        }
        Class<?> instance = type.getInstanceClass();
        if (isNumeric(instance)) {
            String hint = unitHint(v.getObject(), feature, text);
            if (hint != null) {
                return hint;
            }
            boolean whole = instance == int.class || instance == Integer.class || instance == long.class || instance == Long.class
                    || instance == short.class || instance == Short.class;
            return "'" + text + "' is not a number; " + feature.getName() + " is " + (whole ? "a whole number such as 3" : "a decimal number such as 2.5");
        }
        if (instance == boolean.class || instance == Boolean.class) {
            return "'" + text + "' is not a value of " + feature.getName() + "; write true or false";
        }
        return "illegal value for " + feature.getName() + ": '" + text + "'";
    }

    /** '50ms' where a number is due, on an element that has a time unit: say where the unit goes. */
    private static String unitHint(EObject object, EStructuralFeature feature, String text) {
        Matcher m = NUMBER_WITH_UNIT.matcher(text);
        if (!m.matches() || object == null) {
            return null;
        }
        EStructuralFeature unit = object.eClass().getEStructuralFeature("timeUnit");
        if (!(unit instanceof EAttribute) || !(unit.getEType() instanceof EEnum units)
                || units.getEEnumLiteralByLiteral(m.group(2)) == null) {
            return null;
        }
        return "'" + text + "' is not a number: write the number alone and the unit apart, " + feature.getName()
                + "=\"" + m.group(1) + "\" " + unit.getName() + "=\"" + m.group(2) + "\"";
    }

    static boolean isFloating(EStructuralFeature feature) {
        Class<?> c = feature.getEType().getInstanceClass();
        return c == double.class || c == Double.class || c == float.class || c == Float.class;
    }

    /** Why {@code text} cannot be the value of a floating-point attribute, or null when it can (or is not a number at all). */
    static String nonFinite(EStructuralFeature feature, String text) {
        double d;
        try {
            Class<?> c = feature.getEType().getInstanceClass();
            d = c == float.class || c == Float.class ? Float.parseFloat(text.trim()) : Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            return null;
        }
        if (Double.isFinite(d)) {
            return null;
        }
        return feature.getName() + "=\"" + text + "\" is not a finite number" + (Double.isNaN(d) ? "" : " (too large to represent)")
                + "; write a decimal number such as 2.5";
    }

    private static boolean isNumeric(Class<?> c) {
        return c != null && (c.isPrimitive() && c != boolean.class && c != char.class || Number.class.isAssignableFrom(c));
    }

    private static String article(String name) {
        return ("AEIOU".indexOf(name.isEmpty() ? 'x' : name.charAt(0)) >= 0 ? "an " : "a ") + name;
    }

    private static String label(EObject o) {
        EStructuralFeature name = o.eClass().getEStructuralFeature("name");
        Object value = name == null ? null : o.eGet(name);
        return value == null ? "the element" : "'" + value + "'";
    }
}
