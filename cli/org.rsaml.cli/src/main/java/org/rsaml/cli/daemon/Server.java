/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.daemon;

import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;

import org.rsaml.cli.RsamlCli;
import org.rsaml.model.resource.HeapWatch;
import org.rsaml.report.ExitCodes;

/**
 * RsaML's resident process: runs {@code rsaml}'s command lines, sent by {@link Client}, one after the other in one JVM,
 * so that a command does not pay for the JVM's and EMF's start. Each command runs through {@link RsamlCli#run} as in a
 * JVM of its own, in the client's working directory, its standard output and error (also what a library prints on
 * {@code System.out} or {@code System.err} during the command) sent back as it is written, then its exit code. Commands
 * never overlap: {@code System.out} and EMF's registries are the process's.
 *
 * <p>The process listens on a Unix domain socket in a folder of this user's that no one else can enter. It declines
 * the language server (which talks on standard input), answers a command sent with other settings than its own (another
 * jar, a rebuilt one, another JDK, JVM options, locale or umask) by stopping, and stops after its idle time without a
 * command (system property {@code rsaml.daemon.idle}, in seconds; {@link #IDLE} when not given).
 *
 * <p>A command whose result depends on this process's heap, which a JVM of its own would not share (a process started
 * by default has a bounded heap, a JVM of its own the JDK's default), is sent back to run in one (the client then
 * writes nothing of it): one whose models are larger than a sixteenth of the heap ({@link Inputs}), before it runs; one during
 * which the loader gave up on a model as too large for the heap ({@link HeapWatch#givenUp}); one that ran out of memory
 * (the launcher starts this process with {@code -XX:+ExitOnOutOfMemoryError}, so that the JVM's error ends it, and the
 * command, whose client sees it gone, runs in a JVM of its own). A command that completed otherwise keeps its result,
 * also after collections near the heap's limit: running it again would find its own files written. Report files are
 * written whole or not at all, so a command sent back leaves nothing partial; the JVM of its own writes them anew. A command whose client goes away (killed, Ctrl-C) is stopped, as a JVM of its own would be: its thread is
 * interrupted, which ends its file input and output at once and which the loader, the validation and the report files
 * check, so that it writes nothing more; then the process serves the next command. A command not stopped within
 * {@link #STOPPING} stops the process instead.
 *
 * <p>Usage: {@code Server SOCKET SETTINGS}.
 */
public final class Server {

    /** How long the process waits for a command before it stops, unless told otherwise ({@code rsaml.daemon.idle}). */
    static final Duration IDLE = Duration.ofHours(3);

    /** How a process started by default, for a terminal, says so: the value of system property {@code rsaml.daemon.started}. */
    static final String BY_DEFAULT = "default";

    /** How long a command whose client went away may take to stop before the process stops instead. */
    public static final Duration STOPPING = Duration.ofSeconds(2);

    private final Path socket;
    private final String settings;
    private final PrintStream log;
    private final Instant started = Instant.now();
    private final Duration idle;
    private final boolean byDefault;
    private long commands;
    /** Whether the socket is this process's to delete (false once serve has ended and deleted it). */
    private volatile boolean listening = true;
    /** When the last command ended; null while one runs. */
    private Instant idleSince = Instant.now();

    private Server(Path socket, String settings, PrintStream log) {
        this.socket = socket;
        this.settings = settings;
        this.log = log;
        this.idle = idleTime(System.getProperty("rsaml.daemon.idle"));
        this.byDefault = BY_DEFAULT.equals(System.getProperty("rsaml.daemon.started"));
    }

    /** The idle time in whole seconds, {@link #IDLE} when not given or not a positive number. */
    static Duration idleTime(String seconds) {
        try {
            long value = seconds == null ? 0 : Long.parseLong(seconds.trim());
            return value > 0 ? Duration.ofSeconds(value) : IDLE;
        } catch (NumberFormatException e) {
            return IDLE;
        }
    }

    /** A duration as a person says it: "3 hours", "30 minutes", "5 seconds". */
    static String spoken(Duration d) {
        long s = d.toSeconds();
        if (s % 3600 == 0) {
            return s / 3600 + (s == 3600 ? " hour" : " hours");
        }
        if (s % 60 == 0) {
            return s / 60 + (s == 60 ? " minute" : " minutes");
        }
        return s + (s == 1 ? " second" : " seconds");
    }
    public static void main(String[] args) throws IOException, InterruptedException {
        if (args.length != 2) {
            System.err.println("usage: Server SOCKET SETTINGS");
            System.exit(ExitCodes.INPUT_ERROR);
        }
        Path socket = Path.of(args[0]).toAbsolutePath();
        Path folder = socket.getParent();
        if (!Files.isDirectory(folder)) {
            Files.createDirectories(folder, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
        }
        if (!Client.ownFolder(folder)) {
            System.err.println("rsaml: not started: " + folder + " must be a folder of this user's that no one else can enter");
            System.exit(ExitCodes.INPUT_ERROR);
        }
        RsamlCli.setUpProcess();
        Server server = new Server(socket, args[1], System.err);
        // One process per socket: the lock is held for the process's life; a process still stopping is waited for.
        try (FileChannel lockFile = FileChannel.open(folder.resolve(socket.getFileName() + ".lock"), StandardOpenOption.CREATE,
                StandardOpenOption.WRITE)) {
            FileLock lock = null;
            for (int i = 0; i < 50 && lock == null; i++) {
                lock = lockFile.tryLock();
                if (lock == null) {
                    Thread.sleep(100);
                }
            }
            if (lock == null) {
                server.log.println("rsaml: another resident process serves " + socket);
                return;
            }
            server.serve();
        }
    }

    private void serve() throws IOException {
        Files.deleteIfExists(socket);
        try (ServerSocketChannel listener = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            try {
                listener.bind(UnixDomainSocketAddress.of(socket));
            } catch (IOException e) {
                // E.g. a path longer than the system allows (108 bytes on Linux): commands run in JVMs of their own.
                log.println("rsaml: the resident process cannot listen on " + socket + ": " + e.getMessage());
                return;
            }
            // Stopped by System.exit (idle, its client gone): the socket goes while this process still holds the lock, so
            // never one a successor has bound since. Stopped otherwise, serve's end deletes it, also holding the lock.
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                try {
                    if (listening) {
                        Files.deleteIfExists(socket);
                    }
                } catch (IOException e) {
                    // the next process deletes it
                }
            }));
            Thread idle = new Thread(this::stopWhenIdle, "rsaml idle check");
            idle.setDaemon(true);
            idle.start();
            log.println("rsaml: resident process " + ProcessHandle.current().pid() + " listening on " + socket + ", " + how());
            while (true) {
                try (SocketChannel channel = listener.accept()) {
                    if (!serve(channel)) {
                        return;
                    }
                } catch (IOException e) {
                    log.println("rsaml: a command's connection failed: " + e);
                }
            }
        } finally {
            listening = false;
            Files.deleteIfExists(socket);
            log.println("rsaml: resident process stopped");
        }
    }

    /** How this process was started: by default or on request, its idle time, its heap. */
    private String how() {
        return (byDefault ? "started by default for a terminal (RSAML_DAEMON=0 turns that off)" : "started on request")
                + "; stops after " + spoken(idle) + " without a command; heap at most "
                + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB";
    }

    private void stopWhenIdle() {
        long check = Math.max(1_000, Math.min(60_000, idle.toMillis() / 4));
        while (true) {
            try {
                Thread.sleep(check);
            } catch (InterruptedException e) {
                return;
            }
            synchronized (this) {
                if (idleSince != null && Duration.between(idleSince, Instant.now()).compareTo(idle) >= 0) {
                    log.println("rsaml: resident process stops after " + spoken(idle) + " without a command");
                    System.exit(0);
                }
            }
        }
    }

    /** Answers one request; false when the process is to stop. */
    private boolean serve(SocketChannel channel) throws IOException {
        ByteBuffer head = read(channel, 12);
        if (head.getInt() != Client.MAGIC) {
            return true;
        }
        int request = head.getInt();
        int count = head.getInt();
        if (count < 2 || count > 1_000_000) {
            return true;
        }
        String[] strings = new String[count];
        for (int i = 0; i < count; i++) {
            int length = read(channel, 4).getInt();
            strings[i] = StandardCharsets.UTF_8.decode(read(channel, length)).toString();
        }
        Frames frames = new Frames(channel);
        if (request == Client.STOP) {
            frames.send(Client.ACCEPTED, new byte[0]);
            frames.exit(ExitCodes.OK);
            log.println("rsaml: resident process stopped on request");
            return false;
        }
        if (request == Client.STATUS) {
            frames.send(Client.ACCEPTED, new byte[0]);
            String status;
            synchronized (this) {
                status = "rsaml: resident process " + ProcessHandle.current().pid() + " running since " + started + ", "
                        + commands + " commands run, listening on " + socket + "\nrsaml: " + how() + "\n";
            }
            if (!strings[0].equals(settings)) {
                status += "rsaml: it was started with other settings than this command's (another jar, JDK, JVM options,"
                        + " locale or umask): the next command replaces it\n";
            }
            frames.send(Client.OUT, status.getBytes(StandardCharsets.UTF_8));
            frames.exit(ExitCodes.OK);
            return true;
        }
        if (!strings[0].equals(settings)) {
            // Another jar (a rebuilt one), JDK or setting: the launcher starts a process for it.
            frames.send(Client.STALE, new byte[0]);
            frames.flush();
            log.println("rsaml: resident process stops: a command came with other settings (a rebuilt jar, another JDK,"
                    + " other JVM options, locale or umask)");
            return false;
        }
        String[] args = Arrays.copyOfRange(strings, 2, count);
        // The language server talks on this process's standard input and output, and picocli reads an argument file
        // (@FILE) from the process's working directory: these run in a JVM of their own.
        // Inputs large for this process's heap run in a JVM of their own, with the JDK's default heap.
        Path workingDirectory = Path.of(strings[1]);
        if (request != Client.RUN || List.of(args).contains("language-server")
                || Arrays.stream(args).anyMatch(arg -> arg.startsWith("@"))
                || Inputs.larger(workingDirectory, args, Runtime.getRuntime().maxMemory() / 16)) {
            frames.send(Client.DECLINED, new byte[0]);
            frames.flush();
            return true;
        }
        frames.send(Client.ACCEPTED, new byte[0]);
        Command command = new Command(channel, Thread.currentThread());
        long givenUp = HeapWatch.givenUp();
        int code = run(command, frames, workingDirectory, args);
        if (command.abandoned == null) {
            if (code == OUT_OF_MEMORY || HeapWatch.givenUp() != givenUp) {
                log.println("rsaml: command " + commands + " found this process's heap too small ("
                        + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB): it runs again in a JVM of its own");
                frames.send(Client.RETRY, new byte[0]);
                frames.flush();
                // What the command left is garbage: the next one starts from a collected heap.
                System.gc();
            } else {
                frames.exit(code);
            }
        }
        return true;
    }

    /** One command run for a client: whether it still runs, and when its client went away (null while it is there). */
    private static final class Command {
        final SocketChannel channel;
        final Thread thread;
        boolean running = true;
        volatile Instant abandoned;

        Command(SocketChannel channel, Thread thread) {
            this.channel = channel;
            this.thread = thread;
        }
    }

    /** What {@link #run} returns for a command that ended in an {@link OutOfMemoryError}: never an exit code of rsaml's. */
    private static final int OUT_OF_MEMORY = -1;

    /** Runs one command line as a JVM of its own would, its output sent as frames. */
    private int run(Command command, Frames frames, Path workingDirectory, String[] args) {
        long number;
        synchronized (this) {
            idleSince = null;
            number = ++commands;
        }
        OutputStream out = frames.stream(Client.OUT);
        OutputStream err = frames.stream(Client.ERR);
        PrintStream systemOut = System.out;
        PrintStream systemErr = System.err;
        Thread watch = new Thread(() -> stopWhenGone(command, number), "rsaml client watch");
        watch.setDaemon(true);
        PrintWriter outWriter = new PrintWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), true);
        PrintWriter errWriter = new PrintWriter(new OutputStreamWriter(err, StandardCharsets.UTF_8), true);
        try {
            System.setOut(new PrintStream(out, true));
            System.setErr(new PrintStream(err, true));
            watch.start();
            return RsamlCli.run(workingDirectory, args, outWriter, errWriter);
        } catch (OutOfMemoryError e) {
            return OUT_OF_MEMORY;
        } catch (RuntimeException | Error e) {
            // RsamlCli.run reports every failure of a command itself: this is the last resort.
            errWriter.println("rsaml: internal error: " + e);
            log.println("rsaml: internal error in a command:");
            e.printStackTrace(log);
            return ExitCodes.INPUT_ERROR;
        } finally {
            outWriter.flush();
            errWriter.flush();
            System.out.flush();
            System.err.flush();
            System.setOut(systemOut);
            System.setErr(systemErr);
            Instant abandoned;
            synchronized (command) {
                command.running = false;
                abandoned = command.abandoned;
                command.notifyAll();
            }
            // No interrupt comes after this: the next accept must not see one (it would close the listening socket).
            Thread.interrupted();
            if (abandoned != null) {
                log.println("rsaml: command " + number + " stopped " + Duration.between(abandoned, Instant.now()).toMillis()
                        + " ms after its client went away");
            }
            synchronized (this) {
                idleSince = Instant.now();
            }
        }
    }

    /**
     * Stops the command when its client goes away while it runs (as Ctrl-C stops a JVM of its own): interrupts its
     * thread, and stops the process if the command has not ended within {@link #STOPPING}.
     */
    private void stopWhenGone(Command command, long number) {
        ByteBuffer buffer = ByteBuffer.allocate(1);
        try {
            while (command.channel.read(buffer) >= 0) {
                buffer.clear();
            }
        } catch (IOException e) {
            // closed: the command ended, or the client went away
        }
        synchronized (command) {
            if (!command.running) {
                return;
            }
            command.abandoned = Instant.now();
            log.println("rsaml: the client of command " + number + " went away while it ran: the command is stopped");
            command.thread.interrupt();
            long deadline = System.nanoTime() + STOPPING.toNanos();
            try {
                for (long left = STOPPING.toNanos(); command.running && left > 0; left = deadline - System.nanoTime()) {
                    command.wait(left / 1_000_000 + 1);
                }
            } catch (InterruptedException e) {
                // not interrupted by anyone: stop as if the time were up
            }
            if (command.running) {
                log.println("rsaml: resident process stops: command " + number + " did not stop within "
                        + STOPPING.toSeconds() + " s of its client going away");
                System.exit(130);
            }
        }
    }

    private static ByteBuffer read(SocketChannel channel, int length) throws IOException {
        if (length < 0 || length > 64 << 20) {
            throw new IOException("malformed request");
        }
        ByteBuffer buffer = ByteBuffer.allocate(length);
        while (buffer.hasRemaining()) {
            if (channel.read(buffer) < 0) {
                throw new IOException("the request ended early");
            }
        }
        return buffer.flip();
    }

    /** The replies to one request, written in the order the command wrote them, buffered until flushed. */
    private static final class Frames {
        private final SocketChannel channel;
        private final ByteBuffer buffer = ByteBuffer.allocate(1 << 16);
        private boolean broken;

        Frames(SocketChannel channel) {
            this.channel = channel;
        }

        synchronized void send(byte type, byte[] data) throws IOException {
            send(type, data, 0, data.length);
        }

        synchronized void send(byte type, byte[] data, int offset, int length) throws IOException {
            if (buffer.remaining() < 5 + length) {
                flush();
            }
            if (buffer.remaining() < 5 + length) {
                write(ByteBuffer.allocate(5).put(type).putInt(length).flip());
                write(ByteBuffer.wrap(data, offset, length));
            } else {
                buffer.put(type).putInt(length).put(data, offset, length);
            }
        }

        synchronized void exit(int code) throws IOException {
            if (buffer.remaining() < 9) {
                flush();
            }
            buffer.put(Client.EXIT).putInt(4).putInt(code);
            flush();
        }

        synchronized void flush() throws IOException {
            buffer.flip();
            try {
                write(buffer);
            } finally {
                buffer.clear();
            }
        }

        private void write(ByteBuffer data) throws IOException {
            if (broken) {
                return; // the client is gone: the command ends as with a closed standard output
            }
            try {
                while (data.hasRemaining()) {
                    channel.write(data);
                }
            } catch (IOException e) {
                broken = true;
                throw e;
            }
        }

        OutputStream stream(byte type) {
            return new OutputStream() {
                @Override
                public void write(int b) throws IOException {
                    write(new byte[] { (byte) b }, 0, 1);
                }

                @Override
                public void write(byte[] b, int off, int len) throws IOException {
                    send(type, b, off, len);
                }

                @Override
                public void flush() throws IOException {
                    Frames.this.flush();
                }
            };
        }
    }
}
