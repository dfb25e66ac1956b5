/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.function.Function;

import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.MessageConsumer;
import org.eclipse.lsp4j.jsonrpc.RemoteEndpoint;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.RequestMessage;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseMessage;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.ide.server.ILanguageServerShutdownAndExitHandler;
import org.eclipse.xtext.ide.server.IMultiRootWorkspaceConfigFactory;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.ProjectManager;
import org.eclipse.xtext.ide.server.ServerModule;
import org.eclipse.xtext.ide.server.WorkspaceManager;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.validation.RsamlValidationSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;
import com.google.inject.util.Modules;

/**
 * The language server of textual RsaML models (Xtext's, over LSP): diagnostics equal to
 * {@code rsaml validate}'s findings, completion, hover with timing, definition, references, rename,
 * symbols and formatting. {@code rsaml language-server} runs it on standard input and output.
 * <p>
 * Whatever the editor sends, the server answers or says on standard error, in one line, what it could not
 * do ({@link ServerLog}): an editor without a workspace folder, a document outside the folders
 * ({@link FilesOutsideFolders}), an unsaved one ({@link UntitledDocuments}), a change to a document never opened ({@link RsamlWorkspaceManager}), a request
 * after {@code shutdown} (refused as the LSP asks), {@code exit} without {@code shutdown}. A request at a position its
 * document no longer has (an edit shortened it) is answered with nothing, as anywhere else with nothing ({@link RsamlLanguageServerImpl}).
 */
public final class RsamlLanguageServer {

    private RsamlLanguageServer() {
    }

    /**
     * Serves one client on the streams until the input ends, and returns the exit code: 0 when the client
     * asked for {@code shutdown} first, 1 otherwise (said on {@code stderr}). An {@code exit} notification ends
     * the process with that code.
     */
    public static int serve(InputStream in, OutputStream out, PrintStream stderr) throws InterruptedException {
        ServerLog.install(stderr);
        RsamlStandaloneSetup.init();
        RsamlValidationSetup.initInBackground();
        RsamlShutdownAndExitHandler lifecycle = new RsamlShutdownAndExitHandler();
        Injector injector = Guice.createInjector(Modules.override(new ServerModule()).with(binder -> {
            binder.bind(WorkspaceManager.class).to(RsamlWorkspaceManager.class);
            binder.bind(ProjectManager.class).to(RsamlProjectManager.class);
            binder.bind(IMultiRootWorkspaceConfigFactory.class).to(FilesOutsideFolders.class);
            binder.bind(ILanguageServerShutdownAndExitHandler.class).toInstance(lifecycle);
        }));
        LanguageServerImpl server = injector.getInstance(RsamlLanguageServerImpl.class);
        UntitledDocuments.register(injector.getInstance(IResourceServiceProvider.Registry.class));
        Launcher<LanguageClient> launcher = new Launcher.Builder<LanguageClient>()
                .setLocalService(server)
                .setRemoteInterface(LanguageClient.class)
                .setInput(in)
                .setOutput(out)
                .wrapMessages(new Session(lifecycle))
                .setExceptionHandler(Session::failure)
                .create();
        server.connect(launcher.getRemoteProxy());
        Future<Void> listening = launcher.startListening();
        try {
            listening.get();
        } catch (ExecutionException e) {
            // The connection ended (the client went away): nothing more to serve.
        }
        return lifecycle.exitCode("the editor closed the connection (end of standard input)");
    }

    /**
     * The session as the protocol sees it: after {@code shutdown} a request gets the error the LSP specification
     * names (InvalidRequest); a request that fails is answered with one line saying why (no stack trace in the
     * error's data, where LSP4J would put it), and said on standard error with the request it answers.
     */
    private static final class Session implements Function<MessageConsumer, MessageConsumer> {
        private final RsamlShutdownAndExitHandler lifecycle;
        private final Map<Object, String> requests = new ConcurrentHashMap<>();
        private volatile MessageConsumer toClient;

        Session(RsamlShutdownAndExitHandler lifecycle) {
            this.lifecycle = lifecycle;
        }

        /**
         * The error a failed request gets, in one line: what could not be read (a file, a model), or for a fault of
         * the server itself (a runtime exception) that it is one, to be reported; never the exception's trace.
         */
        static ResponseError failure(Throwable thrown) {
            if (thrown instanceof ResponseErrorException refused) {
                return refused.getResponseError();
            }
            Throwable cause = thrown;
            while (cause.getCause() != null && cause.getCause() != cause) {
                cause = cause.getCause();
            }
            String message;
            if (cause instanceof RuntimeException || cause instanceof Error || cause.getMessage() == null) {
                message = "an internal error (" + cause.getClass().getSimpleName() + "); please report it with the request";
            } else {
                message = cause.getMessage().replaceAll("\\s+", " ").strip();
                if (message.length() > 300) {
                    message = message.substring(0, 300) + "...";
                }
            }
            return new ResponseError(ResponseErrorCode.InternalError, "RsaML could not answer: " + message, null);
        }

        @Override
        public MessageConsumer apply(MessageConsumer consumer) {
            if (!(consumer instanceof RemoteEndpoint)) {
                toClient = consumer;
                return message -> {
                    if (message instanceof ResponseMessage response && response.getRawId() != null) {
                        String request = requests.remove(response.getRawId());
                        ResponseError error = response.getError();
                        if (error != null && request != null && !routine(error)) {
                            // The request and its document named, in the answer as on standard error.
                            error = new ResponseError(error.getCode(), request + ": " + error.getMessage(), null);
                            response.setError(error);
                            ServerLog.problem(error.getMessage());
                        }
                    }
                    consumer.consume(message);
                };
            }
            return message -> {
                if (message instanceof RequestMessage request && lifecycle.isShutDown()) {
                    String why = "the server is shutting down and accepts only the exit notification";
                    ServerLog.problem(request.getMethod() + " after shutdown: " + why);
                    ResponseMessage refusal = new ResponseMessage();
                    refusal.setRawId(request.getRawId());
                    refusal.setError(new ResponseError(ResponseErrorCode.InvalidRequest, request.getMethod() + " after shutdown: " + why, null));
                    toClient.consume(refusal);
                    return;
                }
                if (message instanceof RequestMessage request && request.getRawId() != null) {
                    requests.put(request.getRawId(), request.getMethod() + document(request.getParams()));
                }
                consumer.consume(message);
            };
        }

        /** An editor cancels requests it no longer needs, and the server those its edits outdate: nothing to say. */
        private static boolean routine(ResponseError error) {
            return error.getCode() == ResponseErrorCode.RequestCancelled.getValue()
                    || error.getCode() == ResponseErrorCode.ContentModified.getValue();
        }

        /** " for URI" when the request is about a document. */
        private static String document(Object params) {
            // Every document request's parameters have getTextDocument() (hover, completion, symbols, formatting, ...).
            try {
                Object id = params == null ? null : params.getClass().getMethod("getTextDocument").invoke(params);
                return id instanceof TextDocumentIdentifier doc ? " for " + doc.getUri() : "";
            } catch (ReflectiveOperationException | RuntimeException e) {
                return "";
            }
        }
    }
}
