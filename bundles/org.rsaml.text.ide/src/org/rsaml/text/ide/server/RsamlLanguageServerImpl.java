/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.util.Collections;
import java.util.List;

import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DocumentHighlight;
import org.eclipse.lsp4j.DocumentHighlightParams;
import org.eclipse.lsp4j.DocumentRangeFormattingParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PrepareRenameDefaultBehavior;
import org.eclipse.lsp4j.PrepareRenameParams;
import org.eclipse.lsp4j.PrepareRenameResult;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.SignatureHelp;
import org.eclipse.lsp4j.SignatureHelpParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.jsonrpc.messages.Either3;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.eclipse.xtext.ide.server.signatureHelp.ISignatureHelpService;
import org.eclipse.xtext.util.CancelIndicator;

/**
 * Xtext's language server, where every request at a position (or over a range) of a document answers "nothing
 * here" when the document no longer has that position: an editor sends a hover, a completion, a go-to, ... for the
 * text it showed, and an edit it sent before may have shortened that text. Xtext would fail inside (its document
 * refuses the offset) and the editor be told of an internal error; the LSP's practice is an empty answer, and the
 * editor asks again for its new text. Each answer is the one Xtext gives where the language offers nothing for the
 * request. The check runs in the request, after every change sent before it, on the document as it is then.
 */
public class RsamlLanguageServerImpl extends LanguageServerImpl {

    @Override
    protected Hover hover(HoverParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? IHoverService.EMPTY_HOVER : super.hover(params, cancelIndicator);
    }

    @Override
    protected Either<List<CompletionItem>, CompletionList> completion(CancelIndicator cancelIndicator, CompletionParams params) {
        return stale(params.getTextDocument(), params.getPosition()) ? Either.forRight(new CompletionList())
                : super.completion(cancelIndicator, params);
    }

    @Override
    protected Either<List<? extends Location>, List<? extends LocationLink>> definition(DefinitionParams params,
            CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? Either.forLeft(Collections.emptyList())
                : super.definition(params, cancelIndicator);
    }

    @Override
    protected List<? extends Location> references(ReferenceParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? Collections.emptyList() : super.references(params, cancelIndicator);
    }

    @Override
    protected List<? extends DocumentHighlight> documentHighlight(DocumentHighlightParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? Collections.emptyList()
                : super.documentHighlight(params, cancelIndicator);
    }

    @Override
    protected SignatureHelp signatureHelp(SignatureHelpParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? ISignatureHelpService.EMPTY
                : super.signatureHelp(params, cancelIndicator);
    }

    @Override
    protected Either3<Range, PrepareRenameResult, PrepareRenameDefaultBehavior> prepareRename(PrepareRenameParams params,
            CancelIndicator cancelIndicator) {
        // null: no rename is possible here (the LSP's answer)
        return stale(params.getTextDocument(), params.getPosition()) ? null : super.prepareRename(params, cancelIndicator);
    }

    @Override
    protected WorkspaceEdit rename(RenameParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getPosition()) ? new WorkspaceEdit() : super.rename(params, cancelIndicator);
    }

    @Override
    protected List<Either<Command, CodeAction>> codeAction(CodeActionParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getRange()) ? Collections.emptyList() : super.codeAction(params, cancelIndicator);
    }

    @Override
    protected List<? extends TextEdit> rangeFormatting(DocumentRangeFormattingParams params, CancelIndicator cancelIndicator) {
        return stale(params.getTextDocument(), params.getRange()) ? Collections.emptyList()
                : super.rangeFormatting(params, cancelIndicator);
    }

    private boolean stale(TextDocumentIdentifier document, Range range) {
        return range != null && stale(document, range.getStart(), range.getEnd());
    }

    /**
     * Whether one of the positions is not in the document as the server has it now (a line it does not have, a
     * character past its line's end). A document the server cannot read is left to the request, which says why.
     */
    private boolean stale(TextDocumentIdentifier document, Position... positions) {
        if (document == null || document.getUri() == null) {
            return false;
        }
        return getWorkspaceManager().doRead(getURI(document), (current, resource) -> {
            if (current == null) {
                return false;
            }
            String text = current.getContents();
            for (Position p : positions) {
                if (p != null && !within(text, p)) {
                    return true;
                }
            }
            return false;
        });
    }

    /**
     * Whether the text has the position: a line it has, a character up to the end of that line (its '\n' not
     * counted), as Xtext's document reads positions into offsets.
     */
    private static boolean within(String text, Position p) {
        if (p.getLine() < 0 || p.getCharacter() < 0) {
            return false;
        }
        int start = 0;
        for (int line = 0; line < p.getLine(); line++) {
            int newline = text.indexOf('\n', start);
            if (newline < 0) {
                return false;
            }
            start = newline + 1;
        }
        int end = text.indexOf('\n', start);
        return p.getCharacter() <= (end < 0 ? text.length() : end) - start;
    }
}
