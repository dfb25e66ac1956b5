/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Draws the two 10x10 decorations the RsaML diagrams put on an element with findings: a red disc with a
 * cross for errors, an amber triangle with a bar for warnings.
 * Run from the repository root: java -Djava.awt.headless=true releng/icons/DrawDecorations.java bundles/org.rsaml.design/icons
 */
public class DrawDecorations {

    public static void main(String[] args) throws Exception {
        File dir = new File(args[0]);
        dir.mkdirs();

        BufferedImage error = image();
        Graphics2D g = graphics(error);
        g.setColor(new Color(0xc0392b));
        g.fill(new Ellipse2D.Double(0, 0, 10, 10));
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(1.6f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(3, 3, 7, 7));
        g.draw(new Line2D.Double(7, 3, 3, 7));
        g.dispose();
        ImageIO.write(error, "png", new File(dir, "error.png"));

        BufferedImage warning = image();
        g = graphics(warning);
        Path2D triangle = new Path2D.Double();
        triangle.moveTo(5, 0);
        triangle.lineTo(10, 10);
        triangle.lineTo(0, 10);
        triangle.closePath();
        g.setColor(new Color(0xf0a000));
        g.fill(triangle);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1.4f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(5, 3.5, 5, 6.5));
        g.fill(new Ellipse2D.Double(4.3, 7.6, 1.4, 1.4));
        g.dispose();
        ImageIO.write(warning, "png", new File(dir, "warning.png"));
    }

    private static BufferedImage image() {
        return new BufferedImage(10, 10, BufferedImage.TYPE_INT_ARGB);
    }

    private static Graphics2D graphics(BufferedImage image) {
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        return g;
    }
}
