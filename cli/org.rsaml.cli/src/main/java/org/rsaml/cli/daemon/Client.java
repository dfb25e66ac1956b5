/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.daemon;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The client of RsaML's resident process ({@link Server}): sends one command line, with its working directory, to the
 * process listening on a Unix domain socket and copies what the command writes to this process's standard output and
 * error, then exits with the command's exit code. It runs in a JVM of its own with nothing but itself on the class
 * path (its own jar, {@code rsaml-client.jar}), so that it starts at about the cost of {@code java -version}.
 *
 * <p>When no resident process serves the command (none listening, one started for another jar, JDK or settings, a
 * folder that is not this user's alone, or a command it does not run), the client writes nothing and exits with
 * {@link #NOT_SERVED}: the launcher then runs the command in a JVM of its own, as without the resident process. What a
 * command writes is held until its exit code comes, so that a command the resident process could not finish as a JVM
 * of its own would (its heap was too small for it, or the process is gone) is also not served, nothing of it written.
 *
 * <p>Usage: {@code Client SOCKET SETTINGS run|status|stop [ARGUMENTS...]}, where SETTINGS names what the launcher
 * would start the resident process with (the jar, the JDK, the JVM options, the locale and umask).
 */
public final class Client {

    /** The exit code of a command no resident process ran (none serves it); never one of {@code rsaml}'s own. */
    public static final int NOT_SERVED = 75;

    /**
     * The exit code of a command that the running resident process sent back to run in a JVM of its own (the language
     * server, an argument file, inputs large for its heap, a model the loader gave up on for its heap): a process
     * serves, so none is to be started.
     */
    public static final int DECLINED_HERE = 76;

    /** The first bytes of every request: the protocol's version. */
    static final int MAGIC = 0x52534d02;

    /** Requests. */
    static final int RUN = 1;
    static final int STATUS = 2;
    static final int STOP = 3;

    /** Replies: each a type byte, a length and that many bytes. */
    static final byte ACCEPTED = 'A';
    static final byte DECLINED = 'D';
    static final byte STALE = 'S';
    static final byte OUT = 'O';
    static final byte ERR = 'E';
    static final byte EXIT = 'X';
    /** The command is to run in a JVM of its own instead (its output, held by the client, is dropped). */
    static final byte RETRY = 'R';

    private Client() {
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }

    static int run(String[] args) {
        if (args.length < 3) {
            return NOT_SERVED;
        }
        int request = switch (args[2]) {
            case "run" -> RUN;
            case "status" -> STATUS;
            case "stop" -> STOP;
            default -> 0;
        };
        Path socket = Path.of(args[0]);
        if (request == 0 || !ownFolder(socket.getParent())) {
            return NOT_SERVED;
        }
        try (SocketChannel channel = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            channel.connect(UnixDomainSocketAddress.of(socket));
            send(channel, request, args);
            return receive(channel);
        } catch (IOException e) {
            // Nobody listening, or a process gone before it accepted the command: nothing was written.
            return NOT_SERVED;
        }
    }

    /**
     * Whether {@code folder} is a real folder (no link) of this process's user (by user id, as the system knows it:
     * the owner of {@code /proc/self}, also without a name in the user database) that no one else can read, write or
     * enter.
     */
    static boolean ownFolder(Path folder) {
        try {
            if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
                return false;
            }
            Map<String, Object> attributes = Files.readAttributes(folder, "unix:uid,mode", LinkOption.NOFOLLOW_LINKS);
            return ((Integer) attributes.get("mode") & 077) == 0
                    && attributes.get("uid").equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid"));
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException | NullPointerException e) {
            return false;
        }
    }

    private static void send(SocketChannel channel, int request, String[] args) throws IOException {
        byte[][] strings = new byte[args.length - 1][];
        strings[0] = args[1].getBytes(StandardCharsets.UTF_8);
        strings[1] = System.getProperty("user.dir").getBytes(StandardCharsets.UTF_8);
        for (int i = 3; i < args.length; i++) {
            strings[i - 1] = args[i].getBytes(StandardCharsets.UTF_8);
        }
        int size = 12;
        for (byte[] s : strings) {
            size += 4 + s.length;
        }
        ByteBuffer buffer = ByteBuffer.allocate(size);
        buffer.putInt(MAGIC).putInt(request).putInt(strings.length);
        for (byte[] s : strings) {
            buffer.putInt(s.length).put(s);
        }
        buffer.flip();
        while (buffer.hasRemaining()) {
            channel.write(buffer);
        }
    }

    /**
     * Holds the replies until the command's exit code, then copies them to this process's output in the order they
     * were written; {@link #NOT_SERVED}, nothing written, when the resident process asks for the command to run
     * elsewhere or is gone before the exit code.
     */
    private static int receive(SocketChannel channel) throws IOException {
        ByteBuffer header = ByteBuffer.allocate(5);
        if (!read(channel, header)) {
            return NOT_SERVED; // gone: nothing was written
        }
        if (header.get(0) != ACCEPTED) {
            return header.get(0) == DECLINED ? DECLINED_HERE : NOT_SERVED; // declined, or stale (the process stops)
        }
        List<byte[]> held = new ArrayList<>();
        List<Byte> types = new ArrayList<>();
        while (true) {
            header.clear();
            if (!read(channel, header)) {
                return NOT_SERVED; // the resident process is gone: the command runs in a JVM of its own
            }
            byte type = header.get(0);
            int length = header.getInt(1);
            if (type == RETRY) {
                return DECLINED_HERE;
            }
            if (length < 0) {
                return NOT_SERVED;
            }
            ByteBuffer body = ByteBuffer.allocate(length);
            if (!read(channel, body)) {
                return NOT_SERVED;
            }
            if (type == EXIT && length == 4) {
                OutputStream out = new FileOutputStream(FileDescriptor.out);
                OutputStream err = new FileOutputStream(FileDescriptor.err);
                boolean outOpen = true;
                boolean errOpen = true;
                for (int i = 0; i < held.size(); i++) {
                    // As a JVM of its own does, a closed standard output or error is not the command's failure.
                    if (types.get(i) == OUT && outOpen) {
                        outOpen = write(out, held.get(i));
                    } else if (types.get(i) == ERR && errOpen) {
                        errOpen = write(err, held.get(i));
                    }
                }
                return body.getInt(0);
            }
            if (type == OUT || type == ERR) {
                held.add(body.array());
                types.add(type);
            }
        }
    }

    private static boolean write(OutputStream stream, byte[] data) {
        try {
            stream.write(data);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** Fills {@code buffer}; false at the end of the stream. */
    private static boolean read(SocketChannel channel, ByteBuffer buffer) throws IOException {
        while (buffer.hasRemaining()) {
            if (channel.read(buffer) < 0) {
                return false;
            }
        }
        buffer.flip();
        return true;
    }
}
