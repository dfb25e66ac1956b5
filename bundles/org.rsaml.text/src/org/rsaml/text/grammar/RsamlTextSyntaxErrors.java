/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.grammar;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.antlr.runtime.MismatchedTokenException;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.rsaml.model.NamedElement;
import org.rsaml.text.grammar.Constructs.Attribute;
import org.rsaml.text.grammar.Constructs.Construct;
import org.rsaml.text.grammar.Constructs.ValueKind;
import org.rsaml.text.services.RsamlTextGrammarAccess;

import com.google.inject.Inject;
import com.google.inject.Singleton;

/**
 * Syntax errors in the words of the language: what was found, what the place takes (the valid values of an
 * enumeration, the units of a time, the entries a concept's braces may hold), as the grammar defines them
 * ({@link Constructs}). The parser's own wording ("mismatched input ... expecting RULE_NUMBER") is the fallback,
 * with its token names made readable.
 */
@Singleton
public class RsamlTextSyntaxErrors extends SyntaxErrorMessageProvider {

    private final Constructs constructs;
    private final String units;

    @Inject
    public RsamlTextSyntaxErrors(RsamlTextGrammarAccess grammar) {
        this.constructs = new Constructs(grammar.getGrammar());
        this.units = String.join(", ", constructs.literalsOf(grammar.getTimeUnitRule().getName()));
    }

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
        RecognitionException e = context.getRecognitionException();
        String message = e == null || !(e.input instanceof TokenStream tokens) ? lexical(context.getDefaultMessage()) : explain(context, e, tokens);
        if (message == null) {
            return new SyntaxErrorMessage(readable(context.getDefaultMessage()), Diagnostic.SYNTAX_DIAGNOSTIC);
        }
        boolean braces = message.startsWith(ENDS_INSIDE) || message.contains(FOLLOWS_THE_END);
        return new SyntaxErrorMessage(message, braces ? UNBALANCED : Diagnostic.SYNTAX_DIAGNOSTIC);
    }

    private String explain(IParserErrorContext context, RecognitionException e, TokenStream tokens) {
        String[] names = context.getTokenNames();
        Token found = e.token;
        boolean end = found == null || found.getType() == Token.EOF;
        String what = end ? "the end of the file" : "'" + found.getText() + "'";
        int at = found != null && found.getTokenIndex() >= 0 ? found.getTokenIndex() : e.index;
        Token previous = previousVisible(tokens, at);
        Token beforePrevious = previous == null ? null : previousVisible(tokens, previous.getTokenIndex());
        if (previous == null) {
            return end ? "the file holds no model: a textual RsaML model starts with '" + START + "'"
                    : "architecture".equals(found.getText()) ? null
                            : what + " does not start a model: a textual RsaML model starts with '" + START + "'";
        }
        Construct construct = construct(context.getCurrentContext());
        if (e instanceof MismatchedTokenException m && m.expecting == Token.EOF) {
            return what + FOLLOWS_THE_END + ": a file holds one architecture, and nothing but comments follows its closing '}'";
        }
        if (",".equals(previous.getText()) && !end) {
            return what + " is not a name: after ',' write the next name of the list";
        }
        if (construct == null) {
            return null;
        }
        if (previous != null && isKeyword(previous, names)) {
            Attribute attribute = construct.attribute(previous.getText());
            if (attribute != null) {
                String example = attribute.keyword() + " " + attribute.sample();
                return switch (attribute.kind()) {
                    case ENUM -> what + " is not a valid value of '" + attribute.keyword() + "': write one of " + String.join(", ", attribute.literals());
                    case TIME -> what + " is not a time: '" + attribute.keyword() + "' takes a number and its unit (" + units + "), as in '"
                            + example + "'";
                    default -> what + " is not " + attribute.describe() + ": '" + attribute.keyword() + "' takes " + attribute.describe()
                            + ", as in '" + example + "'";
                };
            }
        }
        if (beforePrevious != null && isKeyword(beforePrevious, names)) {
            Attribute attribute = construct.attribute(beforePrevious.getText());
            if (attribute != null && attribute.kind() == ValueKind.TIME) {
                return what + " is not a unit of time: write one of " + units + " after the number, as in '" + attribute.keyword() + " "
                        + previous.getText() + " ms'";
            }
        }
        String subject = subject(construct, context.getCurrentContext());
        if (end && construct.hasBody()) {
            return ENDS_INSIDE + subject + ": a '}' is missing to close it";
        }
        boolean closeExpected = e instanceof MismatchedTokenException m && m.expecting >= 0 && m.expecting < names.length
                && "'}'".equals(names[m.expecting]);
        if (construct.hasBody() && closeExpected) {
            return what + " is not part of " + subject + ": inside its braces write " + String.join(", ", construct.members())
                    + ", or '}' to close it";
        }
        return null;
    }

    /** The concept the parser is reading: the one of the element being built. */
    private Construct construct(EObject element) {
        if (element == null) {
            return null;
        }
        Construct found = null;
        for (Construct c : constructs.all()) {
            if (c.type() == element.eClass()) {
                return c;
            }
            if (c.type().isSuperTypeOf(element.eClass()) && found == null) {
                found = c;
            }
        }
        return found;
    }

    private static String subject(Construct construct, EObject element) {
        String kind = construct.keywords().isEmpty() ? Constructs.words(construct.type().getName()) : construct.keywords().get(0);
        if (element instanceof NamedElement named && construct.type().isInstance(element) && named.getName() != null) {
            return kind + " '" + named.getName() + "'";
        }
        return ("aeiou".indexOf(kind.charAt(0)) >= 0 ? "an " : "a ") + kind;
    }

    private static boolean isKeyword(Token token, String[] names) {
        return token.getType() >= 0 && token.getType() < names.length && names[token.getType()] != null
                && names[token.getType()].startsWith("'");
    }

    private static Token previousVisible(TokenStream tokens, int index) {
        for (int i = Math.min(index, tokens.size()) - 1; i >= 0; i--) {
            Token t = tokens.get(i);
            if (t.getChannel() == Token.DEFAULT_CHANNEL) {
                return t;
            }
        }
        return null;
    }

    private static final String START = "architecture NAME {";
    private static final String ENDS_INSIDE = "the file ends inside ";
    private static final String FOLLOWS_THE_END = " follows the end of the model";

    /**
     * The code of an error about the braces that close elements (the file ends inside one, or text follows the last):
     * after an earlier syntax error it is the parser's recovery from that one, not a mistake of its own.
     */
    public static final String UNBALANCED = "org.rsaml.text.unbalancedBraces";

    private static final Pattern UNEXPECTED = Pattern.compile("(?:mismatched|extraneous) input (.*) expecting (.*)");
    private static final Pattern NOT_VIABLE = Pattern.compile("no viable alternative at input (.*)");
    private static final Pattern MISSING = Pattern.compile("missing (.*) at (.*)");

    /** An error of the lexer: the one a user can make is a string without its closing quote. */
    private static String lexical(String message) {
        return message != null && message.contains("expecting '\"'")
                ? "a string in double quotes is not closed: its closing '\"' is missing"
                : readable(message);
    }

    /** The parser's message in words a user knows: what was found, what to write instead. */
    static String readable(String message) {
        if (message == null) {
            return "syntax error";
        }
        String text = message.replace("RULE_NUMBER", "a number").replace("RULE_ID", "a name")
                .replace("RULE_STRING", "a string in double quotes").replace("RULE_ANY_OTHER", "a character RsaML does not use")
                .replace("'<EOF>'", "the end of the file").replace("<EOF>", "the end of the file").replace("EOF", "the end of the file");
        Matcher m = UNEXPECTED.matcher(text);
        if (m.matches()) {
            return m.group(1) + " is not expected here: write " + m.group(2);
        }
        m = NOT_VIABLE.matcher(text);
        if (m.matches()) {
            return m.group(1) + " is not expected here";
        }
        m = MISSING.matcher(text);
        if (m.matches()) {
            return m.group(1) + " is missing before " + m.group(2);
        }
        return text;
    }
}
