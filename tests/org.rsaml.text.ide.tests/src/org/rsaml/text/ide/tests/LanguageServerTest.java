/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CodeActionContext;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DocumentHighlightParams;
import org.eclipse.lsp4j.DocumentRangeFormattingParams;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.DocumentSymbolCapabilities;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PrepareRenameParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.SignatureHelpParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.text.ide.server.RsamlLanguageServer;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The language server through the protocol: an LSP4J client on one end of a pipe, the server on the
 * other, as an editor talks to {@code rsaml language-server}.
 */
class LanguageServerTest {

    private static final String ROBOT = """
            architecture robot {
              declaredLayers 2

              layer perception {
                level 1

                module lidarDriver {
                  type realTime
                  execType periodic
                  period 50 ms
                  deadline 50 ms
                  wcet 5 ms

                  output scan {
                    dataType numeric
                  }
                }
              }

              layer control {
                module localCostmap {
                  execType periodic
                  period 100 ms

                  input scan {
                    dataType numeric
                  }
                }
              }

              connect lidarDriver.scan -> localCostmap.scan
            }
            """;

    @TempDir
    Path workspace;

    private final Client client = new Client();
    /** What the server said on standard error (also shown on the tests' own). */
    private final ByteArrayOutputStream said = new ByteArrayOutputStream();
    private LanguageServer server;
    private Thread serving;

    /** Records what the server sends. */
    static final class Client implements LanguageClient {
        final Map<String, CompletableFuture<List<Diagnostic>>> diagnostics = new ConcurrentHashMap<>();

        CompletableFuture<List<Diagnostic>> diagnosticsOf(String uri) {
            return diagnostics.computeIfAbsent(uri, u -> new CompletableFuture<>());
        }

        @Override
        public void publishDiagnostics(PublishDiagnosticsParams params) {
            CompletableFuture<List<Diagnostic>> future = diagnosticsOf(params.getUri());
            if (!future.complete(params.getDiagnostics())) {
                diagnostics.put(params.getUri(), CompletableFuture.completedFuture(params.getDiagnostics()));
            }
        }

        @Override
        public void telemetryEvent(Object object) {
        }

        @Override
        public void showMessage(MessageParams messageParams) {
        }

        @Override
        public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams requestParams) {
            return CompletableFuture.completedFuture(null);
        }

        @Override
        public void logMessage(MessageParams message) {
        }
    }

    @BeforeEach
    void start() throws Exception {
        PipedInputStream serverIn = new PipedInputStream(1 << 16);
        PipedOutputStream clientOut = new PipedOutputStream(serverIn);
        PipedInputStream clientIn = new PipedInputStream(1 << 16);
        PipedOutputStream serverOut = new PipedOutputStream(clientIn);
        serving = new Thread(() -> {
            try {
                RsamlLanguageServer.serve(serverIn, serverOut, new PrintStream(new OutputStream() {
                    @Override
                    public void write(int b) {
                        synchronized (said) {
                            said.write(b);
                        }
                        System.err.write(b);
                    }
                }, true, StandardCharsets.UTF_8));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rsaml-language-server");
        serving.setDaemon(true);
        serving.start();
        Launcher<LanguageServer> launcher = LSPLauncher.createClientLauncher(client, clientIn, clientOut);
        launcher.startListening();
        server = launcher.getRemoteProxy();
        InitializeParams init = new InitializeParams();
        init.setRootUri(workspace.toUri().toString());
        init.setWorkspaceFolders(List.of(new org.eclipse.lsp4j.WorkspaceFolder(workspace.toUri().toString(), "workspace")));
        ClientCapabilities capabilities = new ClientCapabilities();
        TextDocumentClientCapabilities text = new TextDocumentClientCapabilities();
        DocumentSymbolCapabilities symbols = new DocumentSymbolCapabilities();
        symbols.setHierarchicalDocumentSymbolSupport(true);
        text.setDocumentSymbol(symbols);
        capabilities.setTextDocument(text);
        capabilities.setWorkspace(new WorkspaceClientCapabilities());
        init.setCapabilities(capabilities);
        server.initialize(init).get(60, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());
    }

    @AfterEach
    void stop() throws Exception {
        // Not exit: the server ends its process on exit, and here it shares the test's.
        server.shutdown().get(30, TimeUnit.SECONDS);
    }

    private String open(String name, String text) throws IOException {
        Path file = workspace.resolve(name);
        Files.writeString(file, text);
        String uri = file.toUri().toString();
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "rsaml", 1, text)));
        return uri;
    }

    /** The position of {@code offsetInMarker} characters into the first {@code marker} of the text. */
    static Position at(String text, String marker, int offsetInMarker) {
        int offset = text.indexOf(marker) + offsetInMarker;
        assertTrue(offset >= offsetInMarker, "the text holds " + marker);
        String before = text.substring(0, offset);
        int line = (int) before.chars().filter(c -> c == '\n').count();
        return new Position(line, offset - before.lastIndexOf('\n') - 1);
    }

    @Test
    void diagnosticsAreTheFindingsOfValidate() throws Exception {
        String text = ModelConverter.toText(org.rsaml.validation.ModelLoader.load(TestRepository.example("exp2-defects.rsaml"),
                "exp2-defects.rsaml").architecture());
        String uri = open("exp2-defects.rsa", text);
        List<Finding> findings = RsamlModelValidator.validate(workspace.resolve("exp2-defects.rsa"), "exp2-defects.rsa");
        List<Diagnostic> diagnostics = client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        assertFalse(findings.isEmpty(), "the defects example has findings");
        Comparator<String> order = Comparator.naturalOrder();
        List<String> expected = findings.stream().map(f -> f.ruleId() + " " + f.severity().label() + " " + (f.line() - 1) + ":"
                + (f.column() - 1) + " " + f.message()).sorted(order).toList();
        List<String> actual = diagnostics.stream().map(d -> d.getCode().getLeft() + " " + d.getSeverity().toString().toLowerCase()
                + " " + d.getRange().getStart().getLine() + ":" + d.getRange().getStart().getCharacter() + " " + d.getMessage().getLeft())
                .sorted(order).toList();
        assertEquals(expected, actual, "one diagnostic per finding: rule id, severity, start and message as rsaml validate reports them");
    }

    @Test
    void aSyntaxErrorIsADiagnosticAtItsPlace() throws Exception {
        String uri = open("broken.rsa", ROBOT.replace("level 1", "level one"));
        List<Diagnostic> diagnostics = client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        assertFalse(diagnostics.isEmpty(), "an error");
        for (Diagnostic d : diagnostics) {
            assertEquals(4, d.getRange().getStart().getLine(), "on the line of 'level one': " + diagnostics);
            assertEquals(org.eclipse.lsp4j.DiagnosticSeverity.Error, d.getSeverity(), "an error: " + diagnostics);
        }
    }

    @Test
    void completesNamesKeywordsAndUnits() throws Exception {
        String text = ROBOT.replace("connect lidarDriver.scan -> localCostmap.scan", "connect ");
        String uri = open("complete.rsa", text);
        client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        List<String> names = labels(server.getTextDocumentService().completion(
                new CompletionParams(new TextDocumentIdentifier(uri), at(text, "connect ", 8))).get(60, TimeUnit.SECONDS));
        assertTrue(names.contains("lidarDriver.scan"), "output ports by name: " + names);
        assertFalse(names.contains("localCostmap.scan"), "no entry port as a source: " + names);
        List<String> units = labels(server.getTextDocumentService().completion(
                new CompletionParams(new TextDocumentIdentifier(uri), at(text, "period 50 ", 10))).get(60, TimeUnit.SECONDS));
        assertTrue(units.containsAll(List.of("ns", "us", "ms", "s")), "the units: " + units);
    }

    private static List<String> labels(org.eclipse.lsp4j.jsonrpc.messages.Either<List<org.eclipse.lsp4j.CompletionItem>,
            org.eclipse.lsp4j.CompletionList> result) {
        List<org.eclipse.lsp4j.CompletionItem> items = result.isLeft() ? result.getLeft() : result.getRight().getItems();
        return items.stream().map(org.eclipse.lsp4j.CompletionItem::getLabel).collect(Collectors.toList());
    }

    @Test
    void hoverShowsTheTiming() throws Exception {
        String uri = open("hover.rsa", ROBOT);
        client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        var hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri), at(ROBOT, "lidarDriver {", 3)))
                .get(60, TimeUnit.SECONDS);
        assertNotNull(hover, "a hover over the module");
        String contents = hover.getContents().getRight().getValue();
        assertTrue(contents.contains("real-time · periodic · T 50.0 ms · D 50.0 ms · C 5.0 ms"),
                "the times with their units, as the diagrams label them: " + contents);
        assertTrue(contents.contains("worst-case response time 5 ms, slack 45 ms"), "the analysed timing: " + contents);
    }

    /**
     * A request at a position that an edit sent before it made stale (a line the text no longer has, a character past the
     * end of its line) is answered with nothing, as where there is nothing, by every request that takes a position or a
     * range: never as an error, and nothing is said of it on standard error. At the text's positions the server answers.
     */
    @Test
    void aPositionAnEditMadeStaleIsAnsweredWithNothing() throws Exception {
        String uri = open("stale.rsa", ROBOT);
        client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        // The editor deletes the second layer and the connection; its requests still name positions of the longer text.
        String shorter = ROBOT.substring(0, ROBOT.indexOf("  layer control")) + "}\n";
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(new VersionedTextDocumentIdentifier(uri, 2),
                List.of(new TextDocumentContentChangeEvent(shorter))));
        TextDocumentIdentifier doc = new TextDocumentIdentifier(uri);
        Position pastTheEnd = at(ROBOT, "connect lidarDriver", 8);
        Position pastTheLine = new Position(at(shorter, "period 50 ms", 0).getLine(), 40);
        assertTrue(pastTheEnd.getLine() > shorter.lines().count(), "the position is past the shorter text's lines");
        var text = server.getTextDocumentService();
        for (Position p : List.of(pastTheEnd, pastTheLine)) {
            String where = " at " + p + ", which the edited text does not have";
            Range range = new Range(new Position(0, 0), p);
            var hover = text.hover(new HoverParams(doc, p)).get(60, TimeUnit.SECONDS);
            assertTrue(hover == null || hover.getContents().isLeft() && hover.getContents().getLeft().isEmpty()
                    || hover.getContents().isRight() && hover.getContents().getRight().getValue().isEmpty(), "no hover" + where + ": " + hover);
            assertEquals(List.of(), labels(text.completion(new CompletionParams(doc, p)).get(60, TimeUnit.SECONDS)), "no completion" + where);
            var definition = text.definition(new DefinitionParams(doc, p)).get(60, TimeUnit.SECONDS);
            assertTrue(definition == null || (definition.isLeft() ? definition.getLeft() : definition.getRight()).isEmpty(),
                    "no definition" + where + ": " + definition);
            assertEmpty(text.references(new ReferenceParams(doc, p, new ReferenceContext(true))).get(60, TimeUnit.SECONDS), "no references" + where);
            assertEmpty(text.documentHighlight(new DocumentHighlightParams(doc, p)).get(60, TimeUnit.SECONDS), "no highlights" + where);
            var signature = text.signatureHelp(new SignatureHelpParams(doc, p)).get(60, TimeUnit.SECONDS);
            assertTrue(signature == null || signature.getSignatures() == null || signature.getSignatures().isEmpty(),
                    "no signature help" + where + ": " + signature);
            assertEquals(null, text.prepareRename(new PrepareRenameParams(doc, p)).get(60, TimeUnit.SECONDS), "nothing to rename" + where);
            WorkspaceEdit rename = text.rename(new RenameParams(doc, p, "laserDriver")).get(60, TimeUnit.SECONDS);
            assertTrue(rename == null || (rename.getChanges() == null || rename.getChanges().isEmpty())
                    && (rename.getDocumentChanges() == null || rename.getDocumentChanges().isEmpty()), "no rename" + where + ": " + rename);
            assertEmpty(text.codeAction(new CodeActionParams(doc, range, new CodeActionContext(List.of()))).get(60, TimeUnit.SECONDS),
                    "no code actions up to" + where);
            assertEmpty(text.rangeFormatting(new DocumentRangeFormattingParams(doc, new FormattingOptions(2, true), range))
                    .get(60, TimeUnit.SECONDS), "no formatting up to" + where);
        }
        var hover = text.hover(new HoverParams(doc, at(shorter, "lidarDriver {", 3))).get(60, TimeUnit.SECONDS);
        assertTrue(hover != null && hover.getContents().getRight().getValue().contains("lidarDriver"),
                "a hover at a position the text has: " + hover);
        String err = said.toString(StandardCharsets.UTF_8);
        assertFalse(err.contains("internal error") || err.contains("could not answer"), "nothing said on standard error:\n" + err);
    }

    private static void assertEmpty(List<?> answer, String what) {
        assertTrue(answer == null || answer.isEmpty(), what + ": " + answer);
    }

    @Test
    void navigatesRenamesSymbolsAndFormats() throws Exception {
        String uri = open("nav.rsa", ROBOT);
        client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
        var definition = server.getTextDocumentService().definition(new DefinitionParams(new TextDocumentIdentifier(uri),
                at(ROBOT, "lidarDriver.scan ->", 13))).get(60, TimeUnit.SECONDS);
        List<? extends Location> targets = definition.getLeft();
        assertEquals(1, targets.size(), "one definition: " + targets);
        assertEquals(at(ROBOT, "output scan", 0).getLine(), targets.get(0).getRange().getStart().getLine(), "the output port: " + targets);

        ReferenceParams references = new ReferenceParams(new TextDocumentIdentifier(uri), at(ROBOT, "output scan", 8), new ReferenceContext(false));
        List<? extends Location> uses = server.getTextDocumentService().references(references).get(60, TimeUnit.SECONDS);
        assertEquals(List.of(at(ROBOT, "connect", 0).getLine()), uses.stream().map(l -> l.getRange().getStart().getLine()).toList(),
                "the connection uses the port");

        WorkspaceEdit rename = server.getTextDocumentService().rename(new RenameParams(new TextDocumentIdentifier(uri),
                at(ROBOT, "module lidarDriver", 8), "laserDriver")).get(60, TimeUnit.SECONDS);
        String renamed = apply(ROBOT, editsOf(rename, uri));
        assertTrue(renamed.contains("module laserDriver {") && renamed.contains("laserDriver.scan -> localCostmap.scan"),
                "the module and its uses renamed:\n" + renamed);

        var symbols = server.getTextDocumentService().documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri)))
                .get(60, TimeUnit.SECONDS);
        List<String> top = symbols.stream().map(s -> s.isRight() ? s.getRight().getName() : s.getLeft().getName()).toList();
        assertTrue(top.toString().contains("robot") || top.toString().contains("perception"), "the outline: " + top);

        String messy = ROBOT.replace("\n  ", "\n").replace("level 1", "level    1");
        String messyUri = open("messy.rsa", messy);
        client.diagnosticsOf(messyUri).get(120, TimeUnit.SECONDS);
        List<? extends TextEdit> format = server.getTextDocumentService().formatting(
                new DocumentFormattingParams(new TextDocumentIdentifier(messyUri), new FormattingOptions(2, true))).get(60, TimeUnit.SECONDS);
        assertEquals(ROBOT, apply(messy, new ArrayList<>(format)), "formatting lays the text out as the writer does");
    }

    private static List<TextEdit> editsOf(WorkspaceEdit edit, String uri) {
        if (edit.getChanges() != null && edit.getChanges().get(uri) != null) {
            return edit.getChanges().get(uri);
        }
        List<TextEdit> edits = new ArrayList<>();
        edit.getDocumentChanges().forEach(c -> {
            if (c.isLeft() && c.getLeft().getTextDocument().getUri().equals(uri)) {
                c.getLeft().getEdits().forEach(e -> edits.add(e.isLeft() ? e.getLeft()
                        : new TextEdit(e.getRight().getRange(), e.getRight().getSnippet().getValue())));
            }
        });
        return edits;
    }

    /** The text with the edits applied (from the last to the first). */
    static String apply(String text, List<TextEdit> edits) {
        List<TextEdit> sorted = new ArrayList<>(edits);
        sorted.sort(Comparator.comparing((TextEdit e) -> offset(text, e.getRange().getStart())).reversed());
        StringBuilder out = new StringBuilder(text);
        for (TextEdit e : sorted) {
            Range r = e.getRange();
            out.replace(offset(text, r.getStart()), offset(text, r.getEnd()), e.getNewText());
        }
        return out.toString();
    }

    private static int offset(String text, Position p) {
        int offset = 0;
        for (int line = 0; line < p.getLine(); line++) {
            offset = text.indexOf('\n', offset) + 1;
        }
        return offset + p.getCharacter();
    }
}
