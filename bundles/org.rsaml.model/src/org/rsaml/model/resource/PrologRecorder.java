/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.Charset;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * What the parser reads. Two jobs:
 * <ul>
 * <li>A lone carriage return becomes a line feed. XML reads both as the same line end (and the
 * document is the same), but the parser miscounts columns after a lone CR; after a line feed it
 * counts them right. A CR followed by LF, or by NEL (one line end in XML 1.1), stays.</li>
 * <li>The bytes up to the root element are kept: SAX reports no event for the XML declaration,
 * so the root's start tag is found in them; they also tell a binary file.</li>
 * </ul>
 */
final class PrologRecorder extends InputStream {

    private static final int LIMIT = 1 << 20;

    /** How code units are laid out: not known yet, single bytes (UTF-8 and the like), UTF-16 LE or BE, or left alone. */
    private enum Units { UNKNOWN, BYTES, UTF16LE, UTF16BE, AS_IS }

    private final InputStream in;
    private final byte[] buffer = new byte[16384];
    /** Next byte to hand out; bytes before {@code ready} are final; {@code limit} ends what was read. */
    private int position;
    private int ready;
    private int limit;
    private boolean eof;
    private Units units = Units.UNKNOWN;
    private ByteArrayOutputStream recorded = new ByteArrayOutputStream();

    PrologRecorder(InputStream in) {
        this.in = in;
    }

    @Override
    public int read() throws IOException {
        byte[] one = new byte[1];
        return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        while (position == ready) {
            if (eof && ready == limit) {
                return -1;
            }
            fill();
        }
        int n = Math.min(len, ready - position);
        System.arraycopy(buffer, position, b, off, n);
        if (recorded != null && recorded.size() < LIMIT) {
            recorded.write(b, off, Math.min(n, LIMIT - recorded.size()));
        }
        position += n;
        return n;
    }

    private void fill() throws IOException {
        if (position > 0) {
            System.arraycopy(buffer, position, buffer, 0, limit - position);
            ready -= position;
            limit -= position;
            position = 0;
        }
        if (!eof && limit < buffer.length) {
            int n = in.read(buffer, limit, buffer.length - limit);
            if (n < 0) {
                eof = true;
            } else {
                limit += n;
            }
        }
        if (units == Units.UNKNOWN) {
            if (limit < 4 && !eof) {
                return;
            }
            units = unitsOf();
        }
        convert();
    }

    private Units unitsOf() {
        int b0 = limit > 0 ? buffer[0] & 0xff : -1;
        int b1 = limit > 1 ? buffer[1] & 0xff : -1;
        int b2 = limit > 2 ? buffer[2] & 0xff : -1;
        if (b0 == 0 && b1 == 0 || b2 == 0 && limit > 3 && buffer[3] == 0 && b0 != 0 && b1 == 0) {
            return Units.AS_IS; // UTF-32 or stranger: left as it is
        }
        if (b0 == 0xff && b1 == 0xfe || b0 == '<' && b1 == 0) {
            return Units.UTF16LE;
        }
        if (b0 == 0xfe && b1 == 0xff || b0 == 0 && b1 == '<') {
            return Units.UTF16BE;
        }
        return Units.BYTES;
    }

    /** Makes final what can be decided: every unit whose successor (two of them for CR NEL) has been read, or all at the end. */
    private void convert() {
        int width = units == Units.BYTES ? 1 : 2;
        if (units == Units.AS_IS) {
            ready = limit;
            return;
        }
        int i = ready;
        for (; i + width <= limit; i += width) {
            if (unit(i) != '\r') {
                continue;
            }
            if (i + 3 * width > limit && !eof) {
                break; // wait for the bytes after the CR
            }
            int next = i + width + width <= limit ? unit(i + width) : -1;
            boolean nel = units == Units.BYTES ? next == 0xc2 && i + 2 < limit && (buffer[i + 2] & 0xff) == 0x85 : next == 0x85;
            if (next != '\n' && !nel) {
                setLineFeed(i);
            }
        }
        ready = eof ? limit : i;
    }

    private int unit(int i) {
        return switch (units) {
            case UTF16LE -> (buffer[i] & 0xff) | (buffer[i + 1] & 0xff) << 8;
            case UTF16BE -> (buffer[i] & 0xff) << 8 | (buffer[i + 1] & 0xff);
            default -> buffer[i] & 0xff;
        };
    }

    private void setLineFeed(int i) {
        switch (units) {
            case UTF16LE -> buffer[i] = '\n';
            case UTF16BE -> buffer[i + 1] = '\n';
            default -> buffer[i] = '\n';
        }
    }

    /** EMF reads the XML declaration ahead only when something is available. */
    @Override
    public int available() throws IOException {
        return ready > position ? ready - position : in.available();
    }

    @Override
    public void close() throws IOException {
        in.close();
    }

    /** The bytes read so far (at most 1 MiB), or an empty array once {@link #stop()} was called. */
    byte[] bytes() {
        return recorded == null ? new byte[0] : recorded.toByteArray();
    }

    void stop() {
        recorded = null;
    }

    /**
     * Where the root element's start tag begins in the bytes read, decoded in {@code encoding} (UTF-8
     * when not known) and counted as the parser counts lines (CR, CRLF, LF; with {@code xml11} also
     * NEL and LS): {line, column}, or {@code null} when it cannot be told.
     */
    int[] rootTagStart(String encoding, boolean xml11) {
        Charset charset;
        try {
            charset = encoding == null ? StandardCharsets.UTF_8 : Charset.forName(encoding);
        } catch (RuntimeException e) {
            return null;
        }
        String text;
        try {
            text = charset.newDecoder().onMalformedInput(CodingErrorAction.REPLACE)
                    .onUnmappableCharacter(CodingErrorAction.REPLACE).decode(ByteBuffer.wrap(bytes())).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            return null;
        }
        int line = 1;
        int column = 1;
        int i = !text.isEmpty() && text.charAt(0) == '\uFEFF' ? 1 : 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            if (c == '<') {
                String skipTo = text.startsWith("<?", i) ? "?>" : text.startsWith("<!--", i) ? "-->" : text.startsWith("<!", i) ? ">" : null;
                if (skipTo == null) {
                    return new int[] { line, column };
                }
                int end = text.indexOf(skipTo, i);
                if (end < 0) {
                    return null;
                }
                end += skipTo.length();
                for (; i < end; i++) {
                    int[] moved = advance(text, i, line, column, xml11);
                    i = moved[0];
                    line = moved[1];
                    column = moved[2];
                }
                continue;
            }
            int[] moved = advance(text, i, line, column, xml11);
            i = moved[0] + 1;
            line = moved[1];
            column = moved[2];
        }
        return null;
    }

    /** Moves past the character at {@code i}: {index of its last char, line, column} afterwards. */
    private static int[] advance(String text, int i, int line, int column, boolean xml11) {
        char c = text.charAt(i);
        if (c == '\r') {
            boolean pair = i + 1 < text.length() && (text.charAt(i + 1) == '\n' || xml11 && text.charAt(i + 1) == '\u0085');
            return new int[] { pair ? i + 1 : i, line + 1, 1 };
        }
        if (c == '\n' || xml11 && (c == '\u0085' || c == '\u2028')) {
            return new int[] { i, line + 1, 1 };
        }
        return new int[] { i, line, column + 1 };
    }
}
