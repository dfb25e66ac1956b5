/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.io.InputStream;
import java.io.OutputStream;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;

import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.ServerModule;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.validation.RsamlValidationSetup;

import com.google.inject.Guice;

/**
 * The language server of textual RsaML models (Xtext's, over LSP): diagnostics equal to
 * {@code rsaml validate}'s findings, completion, hover with timing, definition, references, rename,
 * symbols and formatting. {@code rsaml language-server} runs it on standard input and output.
 */
public final class RsamlLanguageServer {

    private RsamlLanguageServer() {
    }

    /** Serves one client on the streams until it exits or the input ends. */
    public static void serve(InputStream in, OutputStream out) throws InterruptedException {
        RsamlStandaloneSetup.init();
        RsamlValidationSetup.initInBackground();
        LanguageServerImpl server = Guice.createInjector(new ServerModule()).getInstance(LanguageServerImpl.class);
        Launcher<LanguageClient> launcher = Launcher.createLauncher(server, LanguageClient.class, in, out);
        server.connect(launcher.getRemoteProxy());
        Future<Void> listening = launcher.startListening();
        try {
            listening.get();
        } catch (ExecutionException e) {
            // The connection ended (the client went away): nothing more to serve.
        }
    }
}
