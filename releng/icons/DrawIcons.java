/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Draws the 16x16 tree icons of the RsaML concepts, one shape and colour a family, one glyph a concept.
 * Run from the repository root: java -Djava.awt.headless=true releng/icons/DrawIcons.java bundles/org.rsaml.model.edit/icons/full/obj16
 */
public class DrawIcons {
    enum Shape { ROUND, CIRCLE, DIAMOND, TRIANGLE_RIGHT, TRIANGLE_LEFT, HEX, STACK }

    public static void main(String[] args) throws Exception {
        File dir = new File(args[0]);
        dir.mkdirs();
        // structure: blue family; behaviour: green; communication: orange; hardware: grey; mission: purple; data: brown
        draw(dir, "Architecture", Shape.STACK, 0x1f4e9a, "");
        draw(dir, "Layer", Shape.ROUND, 0x3b7dd8, "L");
        draw(dir, "Module", Shape.ROUND, 0x2a6f3a, "M");
        draw(dir, "Function", Shape.CIRCLE, 0x3f9d4f, "f");
        draw(dir, "Action", Shape.CIRCLE, 0x7cc47f, "a");
        draw(dir, "RTAction", Shape.CIRCLE, 0xc0392b, "a");
        draw(dir, "EntryPort", Shape.TRIANGLE_RIGHT, 0xe67e22, "");
        draw(dir, "OutputPort", Shape.TRIANGLE_LEFT, 0xd35400, "");
        draw(dir, "Connection", Shape.ROUND, 0xf0a030, "\u2192");
        draw(dir, "Inhibitor", Shape.CIRCLE, 0x8e1b1b, "I");
        draw(dir, "Suppressor", Shape.CIRCLE, 0x5b2c6f, "S");
        draw(dir, "Sensor", Shape.HEX, 0x607d8b, "s");
        draw(dir, "Actuator", Shape.HEX, 0x37474f, "A");
        draw(dir, "Mission", Shape.DIAMOND, 0x6a1b9a, "M");
        draw(dir, "Goal", Shape.DIAMOND, 0x9c27b0, "G");
        draw(dir, "Plan", Shape.ROUND, 0x7b1fa2, "P");
        draw(dir, "Activity", Shape.CIRCLE, 0xab47bc, "t");
        draw(dir, "Supervisor", Shape.ROUND, 0x4a148c, "S");
        draw(dir, "Order", Shape.TRIANGLE_RIGHT, 0x8e24aa, "");
        draw(dir, "Database", Shape.ROUND, 0x795548, "D");
        draw(dir, "Knowledge", Shape.CIRCLE, 0xa1887f, "k");
        draw(dir, "Processor", Shape.HEX, 0x455a64, "P");
        draw(dir, "LatencyRequirement", Shape.DIAMOND, 0xc0392b, "t");
    }

    static void draw(File dir, String name, Shape shape, int rgb, String glyph) throws Exception {
        BufferedImage image = new BufferedImage(16, 16, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        Color fill = new Color(rgb);
        java.awt.Shape outline = switch (shape) {
            case ROUND -> new RoundRectangle2D.Double(1, 1, 14, 14, 4, 4);
            case CIRCLE -> new Ellipse2D.Double(1, 1, 14, 14);
            case DIAMOND -> polygon(8, 0.5, 15.5, 8, 8, 15.5, 0.5, 8);
            case TRIANGLE_RIGHT -> polygon(2, 1.5, 15, 8, 2, 14.5);
            case TRIANGLE_LEFT -> polygon(14, 1.5, 1, 8, 14, 14.5);
            case HEX -> polygon(4.5, 1.5, 11.5, 1.5, 15, 8, 11.5, 14.5, 4.5, 14.5, 1, 8);
            case STACK -> null;
        };
        if (shape == Shape.STACK) {
            for (int i = 0; i < 3; i++) {
                g.setColor(fill.brighter());
                g.fill(new RoundRectangle2D.Double(1, 1 + i * 5, 14, 4, 2, 2));
                g.setColor(fill.darker());
                g.draw(new RoundRectangle2D.Double(1, 1 + i * 5, 14, 4, 2, 2));
            }
        } else {
            g.setColor(fill);
            g.fill(outline);
            g.setColor(fill.darker());
            g.setStroke(new BasicStroke(1f));
            g.draw(outline);
        }
        if (!glyph.isEmpty()) {
            g.setColor(Color.WHITE);
            g.setFont(new Font("DejaVu Sans", Font.BOLD, 10));
            int w = g.getFontMetrics().stringWidth(glyph);
            g.drawString(glyph, (16 - w) / 2f, 12f);
        }
        g.dispose();
        ImageIO.write(toIndexed(image), "gif", new File(dir, name + ".gif"));
    }

    /** EMF looks icons up as GIF: a palette of the icon's colours, index 0 transparent. */
    static BufferedImage toIndexed(BufferedImage argb) {
        java.util.LinkedHashMap<Integer, Integer> palette = new java.util.LinkedHashMap<>();
        palette.put(0, 0);
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 16; x++) {
                int p = argb.getRGB(x, y);
                if ((p >>> 24) >= 96) {
                    palette.putIfAbsent(p | 0xff000000, palette.size());
                }
            }
        }
        int n = palette.size();
        byte[] r = new byte[n], g = new byte[n], b = new byte[n];
        palette.forEach((rgb, i) -> {
            r[i] = (byte) (rgb >> 16);
            g[i] = (byte) (rgb >> 8);
            b[i] = (byte) (int) rgb;
        });
        int bits = Math.max(1, 32 - Integer.numberOfLeadingZeros(n - 1));
        java.awt.image.IndexColorModel model = new java.awt.image.IndexColorModel(bits, n, r, g, b, 0);
        BufferedImage indexed = new BufferedImage(16, 16, BufferedImage.TYPE_BYTE_INDEXED, model);
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 16; x++) {
                int p = argb.getRGB(x, y);
                indexed.getRaster().setSample(x, y, 0, (p >>> 24) >= 96 ? palette.get(p | 0xff000000) : 0);
            }
        }
        return indexed;
    }

    static java.awt.Shape polygon(double... xy) {
        Path2D.Double p = new Path2D.Double();
        p.moveTo(xy[0], xy[1]);
        for (int i = 2; i < xy.length; i += 2) {
            p.lineTo(xy[i], xy[i + 1]);
        }
        p.closePath();
        return p;
    }
}
