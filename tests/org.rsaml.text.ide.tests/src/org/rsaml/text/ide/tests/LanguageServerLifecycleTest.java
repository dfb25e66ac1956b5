/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageServer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.TestRepository;

/**
 * {@code rsaml language-server} as a separate process, spoken to over its standard input and output as an editor
 * does, through what editors really send at the edges of a session: no workspace folder (a single file opened in
 * VS Code; Helix, Kate, vim clients), only the deprecated {@code rootPath}, a folder that does not exist, an
 * untitled document, a file not saved yet, a request it cannot answer, a change to a document never opened, a request after {@code shutdown}, {@code exit} without
 * {@code shutdown}, standard input closed. None may print a stack trace; each ends with the LSP's exit code.
 */
class LanguageServerLifecycleTest {

    /** A known defect of experiment 2, as {@code rsaml validate} reports it (README). */
    private static final String RSA_08 = "Module 'resourceChecker' takes 2.5 ms but layer 'control' allows at most 2.0 ms";

    private static final Path EXP2 = TestRepository.root().resolve("examples-text/exp2-defects.rsa");

    @TempDir
    Path dir;

    private Process process;
    private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
    private Thread stderrReader;
    private final LanguageServerTest.Client client = new LanguageServerTest.Client();
    private LanguageServer server;

    @AfterEach
    void end() {
        if (process != null && process.isAlive()) {
            process.destroyForcibly();
        }
    }

    /** Starts {@code java -jar rsaml.jar language-server} and connects an LSP client to its standard streams. */
    private void start() throws IOException {
        Path jar = Path.of(System.getProperty("rsaml.jar", TestRepository.root() + "/cli/org.rsaml.cli/target/rsaml.jar"));
        assertTrue(Files.isRegularFile(jar), "the runnable jar is built (cli/org.rsaml.cli): " + jar);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        process = new ProcessBuilder(java, "-jar", jar.toString(), "language-server").directory(dir.toFile()).start();
        InputStream err = process.getErrorStream();
        stderrReader = new Thread(() -> {
            try {
                err.transferTo(stderr);
            } catch (IOException e) {
                // the process ended
            }
        }, "language-server-stderr");
        stderrReader.start();
        var launcher = LSPLauncher.createClientLauncher(client, process.getInputStream(), process.getOutputStream());
        launcher.startListening();
        server = launcher.getRemoteProxy();
    }

    private void initialize(InitializeParams params) throws Exception {
        params.setCapabilities(new ClientCapabilities());
        assertNotNull(server.initialize(params).get(60, TimeUnit.SECONDS).getCapabilities(), "the server's capabilities" + said());
        server.initialized(new InitializedParams());
    }

    /** What the server printed on standard error (complete once the process has ended). */
    private String said() {
        synchronized (stderr) {
            return "\nstandard error:\n" + stderr.toString(StandardCharsets.UTF_8);
        }
    }

    /** Waits for the process to end and returns its exit code; standard error never holds a stack trace. */
    private int ended() throws Exception {
        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "the server ends" + said());
        stderrReader.join(10_000);
        String err = stderr.toString(StandardCharsets.UTF_8);
        assertFalse(err.contains("\tat ") || err.contains("Caused by:") || err.contains("Exception in thread") || err.contains("SEVERE"),
                "no stack trace:" + said());
        return process.exitValue();
    }

    private void shutdownAndExit() throws Exception {
        server.shutdown().get(30, TimeUnit.SECONDS);
        server.exit();
        assertEquals(0, ended(), "shutdown, then exit: exit code 0" + said());
    }

    private String open(String uri, String text) {
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "rsaml", 1, text)));
        return uri;
    }

    private List<Diagnostic> diagnosticsOf(String uri) throws Exception {
        return client.diagnosticsOf(uri).get(120, TimeUnit.SECONDS);
    }

    private static boolean hasRsa08(List<Diagnostic> diagnostics) {
        return diagnostics.stream().anyMatch(d -> "RSA-08".equals(d.getCode().getLeft()) && RSA_08.equals(d.getMessage().getLeft())
                && d.getRange().getStart().getLine() == 128);
    }

    @Test
    void aFileOpenedWithoutAnyWorkspaceFolder() throws Exception {
        start();
        InitializeParams init = new InitializeParams();
        init.setRootUri(null);
        init.setWorkspaceFolders(null);
        initialize(init);
        String text = Files.readString(EXP2);
        String uri = open(EXP2.toUri().toString(), text);
        List<Diagnostic> diagnostics = diagnosticsOf(uri);
        assertTrue(hasRsa08(diagnostics), "the model's findings, RSA-08 among them, on its line 129: " + diagnostics + said());
        assertEquals(5, diagnostics.stream().filter(d -> d.getSeverity() == org.eclipse.lsp4j.DiagnosticSeverity.Error).count(),
                "the five defects of experiment 2, errors: " + diagnostics);
        assertEquals(List.of("RSA-24"), diagnostics.stream().filter(d -> d.getSeverity() != org.eclipse.lsp4j.DiagnosticSeverity.Error)
                .map(d -> d.getCode().getLeft()).toList(), "and the one warning its expect comment states (functional/m01.f0_m01 not analysed): "
                + diagnostics);

        var hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri),
                LanguageServerTest.at(text, "module resourceChecker", 9))).get(60, TimeUnit.SECONDS);
        assertNotNull(hover, "a hover over the module" + said());
        assertTrue(hover.getContents().getRight().getValue().contains("resourceChecker"), "the hover names the module: " + hover);

        var completion = server.getTextDocumentService().completion(new CompletionParams(new TextDocumentIdentifier(uri),
                LanguageServerTest.at(text, "wcet 2.5 ", 9))).get(60, TimeUnit.SECONDS);
        List<String> units = completion.getLeft() != null ? completion.getLeft().stream().map(CompletionItem::getLabel).toList()
                : completion.getRight().getItems().stream().map(CompletionItem::getLabel).toList();
        assertTrue(units.containsAll(List.of("ns", "us", "ms", "s")), "the units after a time: " + units);
        shutdownAndExit();
    }

    @Test
    void onlyTheDeprecatedRootPath() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("models"));
        Files.copy(EXP2, folder.resolve("exp2-defects.rsa"));
        start();
        InitializeParams init = new InitializeParams();
        init.setRootPath(folder.toString());
        initialize(init);
        // The folder is built without the editor opening anything: its file's findings come.
        String uri = folder.resolve("exp2-defects.rsa").toUri().toString();
        assertTrue(hasRsa08(diagnosticsOf(uri)), "the folder named by rootPath is checked" + said());
        shutdownAndExit();
    }

    @Test
    void aRootUriThatDoesNotExist() throws Exception {
        start();
        InitializeParams init = new InitializeParams();
        String folder = dir.resolve("no-such-folder").toUri().toString();
        init.setRootUri(folder);
        initialize(init);
        String uri = open(EXP2.toUri().toString(), Files.readString(EXP2));
        assertTrue(hasRsa08(diagnosticsOf(uri)), "a file opened still has its findings" + said());
        shutdownAndExit();
        assertTrue(said().contains("rsaml language-server: the workspace folder " + folder + " is not a directory on this machine"),
                "the missing folder is named" + said());
    }

    @Test
    void anUntitledDocument() throws Exception {
        start();
        initialize(new InitializeParams());
        String text = Files.readString(EXP2);
        String untitled = open("untitled:Untitled-1", text);
        assertTrue(hasRsa08(diagnosticsOf(untitled)), "the unsaved text is checked as RsaML text" + said());
        var hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(untitled),
                LanguageServerTest.at(text, "module resourceChecker", 9))).get(60, TimeUnit.SECONDS);
        assertTrue(hover != null && hover.getContents().getRight().getValue().contains("resourceChecker"), "a hover: " + hover + said());
        shutdownAndExit();
    }

    @Test
    void aFileNotSavedYet() throws Exception {
        start();
        initialize(new InitializeParams());
        // A file the editor created and has not written: its text is the editor's, there is nothing on disk.
        String uri = open(dir.resolve("new.rsa").toUri().toString(), Files.readString(EXP2));
        assertTrue(hasRsa08(diagnosticsOf(uri)), "checked from the editor's text" + said());
        shutdownAndExit();
    }

    @Test
    void aChangeToADocumentNeverOpened() throws Exception {
        start();
        initialize(new InitializeParams());
        String never = dir.resolve("never-opened.rsa").toUri().toString();
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(new VersionedTextDocumentIdentifier(never, 2),
                List.of(new TextDocumentContentChangeEvent("architecture a {}\n"))));
        // The server goes on: a document opened after it is checked.
        String uri = open(EXP2.toUri().toString(), Files.readString(EXP2));
        assertTrue(hasRsa08(diagnosticsOf(uri)), "the server keeps working" + said());
        assertFalse(client.diagnostics.containsKey(never), "nothing reported for the document never opened");
        shutdownAndExit();
        assertTrue(said().contains("rsaml language-server: textDocument/didChange for " + never + ", which the editor has not opened"),
                "the ignored change is named" + said());
    }

    @Test
    void aRequestItCannotAnswer() throws Exception {
        start();
        initialize(new InitializeParams());
        // A hover in a document the editor never opened and that is not on disk.
        String missing = dir.resolve("missing.rsa").toUri().toString();
        CompletableFuture<?> hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(missing), new Position(0, 0)));
        ExecutionException failed = assertThrows(ExecutionException.class, () -> hover.get(30, TimeUnit.SECONDS), "an error");
        var error = ((ResponseErrorException) failed.getCause()).getResponseError();
        assertEquals("textDocument/hover for " + missing + ": RsaML could not answer: no such file", error.getMessage(),
                "the error names the request, its document and why, in one line");
        assertEquals(null, error.getData(), "no stack trace in the error's data");
        // The server goes on.
        String uri = open(EXP2.toUri().toString(), Files.readString(EXP2));
        assertTrue(hasRsa08(diagnosticsOf(uri)), "the server keeps working" + said());
        // A position past the document's end (an edit the editor sent made it stale): nothing there, not an error.
        var past = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri), new Position(100_000, 0)))
                .get(30, TimeUnit.SECONDS);
        assertTrue(past == null || past.getContents().isLeft() && past.getContents().getLeft().isEmpty()
                || past.getContents().isRight() && past.getContents().getRight().getValue().isEmpty(), "no hover there: " + past);
        shutdownAndExit();
        assertTrue(said().contains("rsaml language-server: textDocument/hover for " + missing + ": RsaML could not answer: no such file"),
                "the failed request is named with its document" + said());
        assertFalse(said().contains("textDocument/hover for " + uri), "nothing said of the hover past the end" + said());
    }

    @Test
    void aRequestAfterShutdownIsRefused() throws Exception {
        start();
        initialize(new InitializeParams());
        String uri = open(EXP2.toUri().toString(), Files.readString(EXP2));
        diagnosticsOf(uri);
        server.shutdown().get(30, TimeUnit.SECONDS);
        CompletableFuture<?> hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri), new Position(128, 12)));
        ExecutionException refused = assertThrows(ExecutionException.class, () -> hover.get(30, TimeUnit.SECONDS), "refused");
        ResponseErrorException error = (ResponseErrorException) refused.getCause();
        assertEquals(ResponseErrorCode.InvalidRequest.getValue(), error.getResponseError().getCode(), "InvalidRequest, as the LSP asks");
        server.exit();
        assertEquals(0, ended(), "exit after the shutdown: 0" + said());
        assertTrue(said().contains("rsaml language-server: textDocument/hover after shutdown"), "the refusal is named" + said());
    }

    @Test
    void exitWithoutShutdown() throws Exception {
        start();
        initialize(new InitializeParams());
        server.exit();
        assertEquals(1, ended(), "exit without shutdown: 1, as the LSP specification says" + said());
        assertTrue(said().contains("rsaml language-server: exit notification without a shutdown request before it"), "said" + said());
    }

    @Test
    void standardInputClosedAbruptly() throws Exception {
        start();
        initialize(new InitializeParams());
        open(EXP2.toUri().toString(), Files.readString(EXP2));
        process.getOutputStream().close();
        assertEquals(1, ended(), "the editor went away without shutdown: 1" + said());
        assertTrue(said().contains("rsaml language-server: the editor closed the connection"), "said" + said());
    }
}
