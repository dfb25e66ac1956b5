/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The system's headless Chromium driven over the DevTools protocol (the JDK's WebSocket client),
 * so that the HTML report is tested in a real browser without a browser download or a driver.
 */
final class Chromium implements AutoCloseable {

    private static final List<String> EXECUTABLES = List.of("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome");

    private final Process process;
    private final Path profile;
    private final WebSocket socket;
    private final AtomicInteger ids = new AtomicInteger();
    private final Map<Integer, CompletableFuture<JsonObject>> pending = new ConcurrentHashMap<>();

    static Path executable() {
        String configured = System.getenv("RSAML_CHROMIUM");
        if (configured != null && !configured.isBlank()) {
            return Path.of(configured);
        }
        for (String candidate : EXECUTABLES) {
            if (Files.isExecutable(Path.of(candidate))) {
                return Path.of(candidate);
            }
        }
        throw new AssertionError("the browser tests need Chromium: install the Debian package chromium (apt-get install chromium)"
                + " or name the executable in RSAML_CHROMIUM");
    }

    Chromium(Path page, int width, int height) throws Exception {
        profile = Files.createTempDirectory("rsaml-chromium");
        ProcessBuilder builder = new ProcessBuilder(executable().toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--hide-scrollbars", "--user-data-dir=" + profile, "--remote-debugging-port=0",
                "--window-size=" + width + "," + height, page.toUri().toString());
        builder.redirectErrorStream(true);
        builder.redirectOutput(profile.resolve("chromium.log").toFile());
        process = builder.start();
        Path portFile = profile.resolve("DevToolsActivePort");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!Files.exists(portFile) || Files.readAllLines(portFile).isEmpty()) {
            if (!process.isAlive() || System.nanoTime() > deadline) {
                String log = Files.exists(profile.resolve("chromium.log")) ? Files.readString(profile.resolve("chromium.log")) : "";
                close();
                throw new AssertionError("Chromium did not start its DevTools endpoint: " + log);
            }
            Thread.sleep(100);
        }
        int port = Integer.parseInt(Files.readAllLines(portFile).get(0).trim());
        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
        String pageSocket = null;
        while (pageSocket == null) {
            String list = http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/json/list")).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            for (JsonElement target : JsonParser.parseString(list).getAsJsonArray()) {
                JsonObject t = target.getAsJsonObject();
                if ("page".equals(t.get("type").getAsString())) {
                    pageSocket = t.get("webSocketDebuggerUrl").getAsString();
                }
            }
            if (pageSocket == null) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("Chromium opened no page");
                }
                Thread.sleep(100);
            }
        }
        socket = http.newWebSocketBuilder().buildAsync(URI.create(pageSocket), new Listener()).get(30, TimeUnit.SECONDS);
        long loaded = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!"complete".equals(eval("document.readyState"))) {
            if (System.nanoTime() > loaded) {
                throw new AssertionError("the page did not finish loading");
            }
            Thread.sleep(100);
        }
    }

    private final class Listener implements WebSocket.Listener {
        private final StringBuilder message = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            message.append(data);
            if (last) {
                JsonObject json = JsonParser.parseString(message.toString()).getAsJsonObject();
                message.setLength(0);
                if (json.has("id")) {
                    CompletableFuture<JsonObject> future = pending.remove(json.get("id").getAsInt());
                    if (future != null) {
                        future.complete(json);
                    }
                }
            }
            webSocket.request(1);
            return null;
        }
    }

    /** Calls a DevTools method and returns its result. */
    JsonObject call(String method, JsonObject params) throws Exception {
        int id = ids.incrementAndGet();
        JsonObject request = new JsonObject();
        request.addProperty("id", id);
        request.addProperty("method", method);
        request.add("params", params == null ? new JsonObject() : params);
        CompletableFuture<JsonObject> future = new CompletableFuture<>();
        pending.put(id, future);
        socket.sendText(new Gson().toJson(request), true).get(30, TimeUnit.SECONDS);
        JsonObject response = future.get(60, TimeUnit.SECONDS);
        if (response.has("error")) {
            throw new AssertionError(method + " failed: " + response.get("error"));
        }
        return response.getAsJsonObject("result");
    }

    /** Evaluates a JavaScript expression in the page; its value as a string (objects: JSON). */
    String eval(String expression) throws Exception {
        JsonObject params = new JsonObject();
        params.addProperty("expression", "(function(){ var v = (" + expression + "); return typeof v === 'string' ? v : JSON.stringify(v); })()");
        params.addProperty("returnByValue", true);
        JsonObject result = call("Runtime.evaluate", params);
        if (result.has("exceptionDetails")) {
            throw new AssertionError("script failed: " + expression + ": " + result.get("exceptionDetails"));
        }
        JsonElement value = result.getAsJsonObject("result").get("value");
        return value == null || value.isJsonNull() ? null : value.getAsString();
    }

    JsonElement evalJson(String expression) throws Exception {
        return JsonParser.parseString(eval(expression));
    }

    /** A real mouse click (press and release of the left button) at viewport coordinates. */
    void click(double x, double y) throws Exception {
        for (String type : new String[] { "mouseMoved", "mousePressed", "mouseReleased" }) {
            JsonObject params = new JsonObject();
            params.addProperty("type", type);
            params.addProperty("x", x);
            params.addProperty("y", y);
            params.addProperty("button", type.equals("mouseMoved") ? "none" : "left");
            params.addProperty("clickCount", type.equals("mouseMoved") ? 0 : 1);
            call("Input.dispatchMouseEvent", params);
        }
    }

    /** Clicks the centre of the first element matching a CSS selector, scrolled into view. */
    void click(String selector) throws Exception {
        JsonArray box = evalJson("(function(){ var e = document.querySelectorAll(" + new Gson().toJson(selector) + ")[0];"
                + " e.scrollIntoView({block: 'center'}); var r = e.getBoundingClientRect();"
                + " return [r.left + r.width / 2, r.top + r.height / 2]; })()").getAsJsonArray();
        click(box.get(0).getAsDouble(), box.get(1).getAsDouble());
    }

    byte[] screenshot() throws Exception {
        JsonObject params = new JsonObject();
        params.addProperty("format", "png");
        return Base64.getDecoder().decode(call("Page.captureScreenshot", params).get("data").getAsString());
    }

    @Override
    public void close() throws IOException {
        if (socket != null) {
            socket.abort();
        }
        process.destroy();
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try (Stream<Path> files = Files.walk(profile)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
