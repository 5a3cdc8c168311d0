package particlelab.view;

import java.awt.Font;
import java.awt.FontFormatException;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.font.FontRenderContext;
import java.awt.font.GlyphVector;
import java.awt.font.LineMetrics;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * Makes the HUD's bitmap font: renders every character of {@link HudFont#CHARACTERS} from a
 * TrueType font with Java's own rasteriser (AWT, antialiased, whole-pixel advances) into one
 * PNG page, white glyphs on transparent, and writes the AngelCode text {@code .fnt} that
 * jME's {@code BitmapFontLoader} reads beside it. A build tool, not used by the running app.
 *
 * <pre>
 *   gradle font          (DejaVu Sans Condensed, fonts-dejavu-core, into assets/Fonts)
 *   java -cp CLASSPATH particlelab.view.FontGenerator FONT.ttf OUT_DIR
 * </pre>
 *
 * The output depends only on the font file and the JDK's rasteriser, so the same command
 * gives the same files; see {@code assets/Fonts/README.md}.
 */
public final class FontGenerator {

    /** The size glyphs are rendered at (in pixels): big enough for a projector's title. */
    public static final int RENDER_SIZE = 48;
    /** Transparent pixels kept around every glyph, so that mipmaps do not mix neighbours. */
    private static final int PADDING = 2;
    private static final int SPACING = 4;
    private static final int MIN_PAGE_SIZE = 256;
    private static final int MAX_PAGE_SIZE = 4096;

    private FontGenerator() {
    }

    /**
     * Generate the font from a shell.
     *
     * @param args the TrueType file and the output folder
     * @throws IOException if a file cannot be read or written
     * @throws FontFormatException if the font file is not a TrueType font
     */
    public static void main(String[] args) throws IOException, FontFormatException {
        if (args.length != 2) {
            System.err.println("usage: FontGenerator FONT.ttf OUT_DIR");
            System.exit(2);
        }
        File out = new File(args[1]);
        if (!out.isDirectory() && !out.mkdirs()) {
            throw new IOException("cannot create the folder " + out);
        }
        Font font = Font.createFont(Font.TRUETYPE_FONT, new File(args[0]))
                .deriveFont((float) RENDER_SIZE);
        generate(font, out, HudFont.BASE_NAME);
        System.out.println("wrote " + new File(out, HudFont.BASE_NAME + ".fnt") + " and "
                + new File(out, HudFont.BASE_NAME + ".png"));
    }

    /**
     * Render the characters and write {@code baseName.png} and {@code baseName.fnt}.
     *
     * @param font the font at its render size (not null)
     * @param folder where to write (an existing folder)
     * @param baseName the files' name without extension (not null)
     * @throws IOException if a file cannot be written, or the font lacks a character
     */
    static void generate(Font font, File folder, String baseName) throws IOException {
        FontRenderContext context = new FontRenderContext(null, true, false);
        String characters = HudFont.CHARACTERS;
        List<Glyph> glyphs = new ArrayList<>();
        for (int i = 0; i < characters.length(); ++i) {
            char c = characters.charAt(i);
            if (!font.canDisplay(c)) {
                throw new IOException(font.getFontName() + " has no glyph for U+"
                        + String.format("%04X", (int) c));
            }
            GlyphVector vector = font.createGlyphVector(context, String.valueOf(c));
            Rectangle bounds = vector.getPixelBounds(context, 0f, 0f);
            int advance = Math.round(vector.getGlyphMetrics(0).getAdvanceX());
            glyphs.add(new Glyph(c, vector, bounds, advance));
        }
        LineMetrics metrics = font.getLineMetrics(characters, context);
        int base = (int) Math.ceil(metrics.getAscent());
        int lineHeight = (int) Math.ceil(metrics.getAscent() + metrics.getDescent()
                + metrics.getLeading());
        int pageSize = MIN_PAGE_SIZE;
        while (!pack(glyphs, pageSize)) {
            pageSize *= 2;
            if (pageSize > MAX_PAGE_SIZE) {
                throw new IOException("the glyphs do not fit a " + MAX_PAGE_SIZE + " page");
            }
        }
        BufferedImage page = new BufferedImage(pageSize, pageSize, BufferedImage.TYPE_INT_ARGB);
        Graphics2D graphics = page.createGraphics();
        graphics.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING,
                RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        graphics.setRenderingHint(RenderingHints.KEY_FRACTIONALMETRICS,
                RenderingHints.VALUE_FRACTIONALMETRICS_OFF);
        graphics.setColor(java.awt.Color.WHITE);
        for (Glyph glyph : glyphs) {
            graphics.drawGlyphVector(glyph.vector, glyph.x + PADDING - glyph.bounds.x,
                    glyph.y + PADDING - glyph.bounds.y);
        }
        graphics.dispose();
        ImageIO.write(page, "png", new File(folder, baseName + ".png"));
        try (PrintWriter fnt = new PrintWriter(new File(folder, baseName + ".fnt"),
                StandardCharsets.US_ASCII)) {
            fnt.printf("info face=\"%s\" size=%d bold=0 italic=0 charset=\"\" unicode=1"
                    + " stretchH=100 smooth=1 aa=1 padding=%d,%d,%d,%d spacing=%d,%d%n",
                    font.getFontName().replace(' ', '_'), RENDER_SIZE, PADDING, PADDING,
                    PADDING, PADDING, SPACING, SPACING);
            fnt.printf("common lineHeight=%d base=%d scaleW=%d scaleH=%d pages=1 packed=0%n",
                    lineHeight, base, pageSize, pageSize);
            fnt.printf("page id=0 file=\"%s.png\"%n", baseName);
            fnt.printf("chars count=%d%n", glyphs.size());
            for (Glyph glyph : glyphs) {
                int width = glyph.bounds.isEmpty() ? 0 : glyph.bounds.width + 2 * PADDING;
                int height = glyph.bounds.isEmpty() ? 0 : glyph.bounds.height + 2 * PADDING;
                fnt.printf("char id=%d x=%d y=%d width=%d height=%d xoffset=%d yoffset=%d"
                        + " xadvance=%d page=0 chnl=15%n", (int) glyph.character, glyph.x,
                        glyph.y, width, height, glyph.bounds.x - PADDING,
                        base + glyph.bounds.y - PADDING, glyph.advance);
            }
        }
    }

    /**
     * Place the glyphs in rows on a square page.
     *
     * @return true if they all fit
     */
    private static boolean pack(List<Glyph> glyphs, int pageSize) {
        int x = SPACING;
        int y = SPACING;
        int rowHeight = 0;
        for (Glyph glyph : glyphs) {
            int width = glyph.bounds.width + 2 * PADDING;
            int height = glyph.bounds.height + 2 * PADDING;
            if (x + width + SPACING > pageSize) {
                x = SPACING;
                y += rowHeight + SPACING;
                rowHeight = 0;
            }
            glyph.x = x;
            glyph.y = y;
            x += width + SPACING;
            rowHeight = Math.max(rowHeight, height);
        }
        return y + rowHeight + SPACING <= pageSize;
    }

    /** One character's outline, its pixel bounds about the pen position, and its place. */
    private static final class Glyph {
        final char character;
        final GlyphVector vector;
        final Rectangle bounds;
        final int advance;
        int x;
        int y;

        Glyph(char character, GlyphVector vector, Rectangle bounds, int advance) {
            this.character = character;
            this.vector = vector;
            this.bounds = bounds;
            this.advance = advance;
        }
    }
}
