/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.conversion;

import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.conversion.impl.AbstractDeclarativeValueConverterService;
import org.eclipse.xtext.nodemodel.INode;
import org.rsaml.text.naming.RsamlTextQualifiedNameConverter;
import org.rsaml.text.naming.RsamlTextSyntax;
import org.rsaml.text.serializer.RsamlTextWriter;

import com.google.inject.Inject;

/** Text to values and back for the terminals and data type rules of RsamlText.xtext. */
public class RsamlTextValueConverters extends AbstractDeclarativeValueConverterService {

    @Inject
    private RsamlTextSyntax syntax;

    @Inject
    private RsamlTextQualifiedNameConverter qualifiedNames;

    @ValueConverter(rule = "ID")
    public IValueConverter<String> ID() {
        return new Converter<>() {
            @Override
            public String toValue(String string, INode node) {
                return string == null ? null : string.startsWith("^") ? string.substring(1) : string;
            }

            @Override
            public String toString(String value) {
                return syntax.isKeyword(value) ? "^" + value : value;
            }
        };
    }

    @ValueConverter(rule = "STRING")
    public IValueConverter<String> STRING() {
        return new Converter<>() {
            @Override
            public String toValue(String string, INode node) {
                return string == null ? null : unquote(string, node);
            }

            @Override
            public String toString(String value) {
                return RsamlTextSyntax.quote(value);
            }
        };
    }

    @ValueConverter(rule = "Name")
    public IValueConverter<String> Name() {
        return new Converter<>() {
            @Override
            public String toValue(String string, INode node) {
                if (string == null) {
                    return null;
                }
                String text = string.strip();
                return text.startsWith("\"") ? unquote(text, node) : text.startsWith("^") ? text.substring(1) : text;
            }

            @Override
            public String toString(String value) {
                return syntax.declaredName(value);
            }
        };
    }

    @ValueConverter(rule = "QualifiedName")
    public IValueConverter<String> QualifiedName() {
        return new Converter<>() {
            @Override
            public String toValue(String string, INode node) {
                try {
                    return string == null ? null : qualifiedNames.toString(qualifiedNames.toQualifiedName(string));
                } catch (IllegalArgumentException e) {
                    throw new ValueConverterException(e.getMessage(), node, null);
                }
            }

            @Override
            public String toString(String value) {
                return value;
            }
        };
    }

    @ValueConverter(rule = "Real")
    public IValueConverter<Double> Real() {
        return new Converter<>() {
            @Override
            public Double toValue(String string, INode node) {
                if (string == null) {
                    return null;
                }
                String text = string.replaceAll("\\s+", "");
                switch (text) {
                    case "NaN":
                        return Double.NaN;
                    case "Infinity":
                        return Double.POSITIVE_INFINITY;
                    case "-Infinity":
                        return Double.NEGATIVE_INFINITY;
                    default:
                        try {
                            return Double.valueOf(text);
                        } catch (NumberFormatException e) {
                            throw new ValueConverterException("'" + text + "' is not a number; write a decimal number such as 50 or 2.5", node, null);
                        }
                }
            }

            @Override
            public String toString(Double value) {
                return RsamlTextWriter.number(value);
            }
        };
    }

    @ValueConverter(rule = "Integer")
    public IValueConverter<Integer> Integer() {
        return new Converter<>() {
            @Override
            public Integer toValue(String string, INode node) {
                if (string == null) {
                    return null;
                }
                try {
                    return java.lang.Integer.valueOf(string.strip());
                } catch (NumberFormatException e) {
                    throw new ValueConverterException("'" + string.strip() + "' is not a whole number between "
                            + java.lang.Integer.MIN_VALUE + " and " + java.lang.Integer.MAX_VALUE + "; write one such as 2", node, null);
                }
            }

            @Override
            public String toString(Integer value) {
                return value.toString();
            }
        };
    }

    private static String unquote(String text, INode node) {
        try {
            return RsamlTextSyntax.unquote(text);
        } catch (IllegalArgumentException e) {
            throw new ValueConverterException(e.getMessage(), node, null);
        }
    }

    /** A converter that is also given the rule it converts (not needed here). */
    private abstract static class Converter<T> implements IValueConverter<T> {
    }
}
