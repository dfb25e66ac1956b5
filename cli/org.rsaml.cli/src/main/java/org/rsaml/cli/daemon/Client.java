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
import java.util.Map;

/**
 * The client of RsaML's resident process ({@link Server}): sends one command line, with its working directory, to the
 * process listening on a Unix domain socket and copies what the command writes to this process's standard output and
 * error, then exits with the command's exit code. It runs in a JVM of its own with nothing but itself on the class
 * path (its own jar, {@code rsaml-client.jar}), so that it starts at about the cost of {@code java -version}.
 *
 * <p>When no resident process serves the command (none listening, one started for another jar, JDK or settings, a
 * folder that is not this user's alone, or a command it does not run), the client writes nothing and exits with
 * {@link #NOT_SERVED}: the launcher then runs the command in a JVM of its own, as without the resident process.
 *
 * <p>Usage: {@code Client SOCKET SETTINGS run|status|stop [ARGUMENTS...]}, where SETTINGS names what the launcher
 * would start the resident process with (the jar, the JDK, the JVM options, the locale and umask).
 */
public final class Client {

    /** The exit code of a command the resident process did not run; never one of {@code rsaml}'s own. */
    public static final int NOT_SERVED = 75;

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

    /** Copies the replies to this process's output until the command's exit code. */
    private static int receive(SocketChannel channel) throws IOException {
        ByteBuffer header = ByteBuffer.allocate(5);
        if (!read(channel, header) || header.get(0) != ACCEPTED) {
            return NOT_SERVED; // declined, stale, or gone: nothing was written
        }
        OutputStream out = new FileOutputStream(FileDescriptor.out);
        OutputStream err = new FileOutputStream(FileDescriptor.err);
        boolean outOpen = true;
        boolean errOpen = true;
        ByteBuffer body = ByteBuffer.allocate(65536);
        while (true) {
            header.clear();
            if (!read(channel, header)) {
                break;
            }
            byte type = header.get(0);
            int length = header.getInt(1);
            if (length < 0) {
                break;
            }
            if (body.capacity() < length) {
                body = ByteBuffer.allocate(length);
            }
            body.clear().limit(length);
            if (!read(channel, body)) {
                break;
            }
            if (type == EXIT && length == 4) {
                return body.getInt(0);
            }
            // As a JVM of its own does, a closed standard output or error is not the command's failure.
            if (type == OUT && outOpen) {
                outOpen = write(out, body, length);
            } else if (type == ERR && errOpen) {
                errOpen = write(err, body, length);
            }
        }
        byte[] message = ("rsaml: the resident process stopped during the command (its log is " + log(channel)
                + "); run it again, or without RSAML_DAEMON\n").getBytes(StandardCharsets.UTF_8);
        write(err, ByteBuffer.wrap(message), message.length);
        return 2;
    }

    private static String log(SocketChannel channel) {
        try {
            return channel.getRemoteAddress() + ".log";
        } catch (IOException e) {
            return "beside its socket";
        }
    }

    private static boolean write(OutputStream stream, ByteBuffer body, int length) {
        try {
            stream.write(body.array(), 0, length);
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
