package particlelab.view;

import com.jme3.font.BitmapCharacter;
import com.jme3.font.BitmapCharacterSet;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;

/**
 * A text drawn with a jME bitmap font, glyph for glyph where jME's {@code BitmapText} puts
 * them (left-aligned, top at the node's origin, one line per {@code '\n'}, kerning applied),
 * but which allocates nothing when its text changes: {@code BitmapText.setText} copies the
 * text into a new String and builds a linked list of new glyph quads each time, so a HUD
 * whose numbers change every refresh made garbage every refresh.
 *
 * <p>The glyphs go into one mesh whose position, texture coordinate, colour and index
 * buffers are allocated at a capacity and rewritten in place; glyphs beyond the text are
 * collapsed onto the origin, where they draw nothing. The buffers grow (allocating, rarely)
 * only when a text is longer than any before it. The text is copied from a
 * {@link CharSequence}, so a caller can hand over its reused {@link StringBuilder}. The size
 * is a scale of the child geometry, so changing it rewrites nothing.
 *
 * <p>Only single-page fonts are drawn (the app's {@link HudFont} has one page).
 */
public final class HudText extends Node {

    /** The most characters one text may hold: four vertices each, indexed by 16-bit shorts. */
    public static final int MAX_GLYPHS = (Short.MAX_VALUE * 2 + 1) / 4;
    /** The glyphs the buffers hold at first. */
    private static final int INITIAL_CAPACITY = 64;
    private static final int VERTICES_PER_GLYPH = 4;
    private static final int INDICES_PER_GLYPH = 6;
    private static final int POSITION_COMPONENTS = 3;
    private static final int TEX_COORD_COMPONENTS = 2;
    private static final int COLOR_COMPONENTS = 4;

    private final BitmapFont font;
    private final BitmapCharacterSet charSet;
    private final Geometry geometry;
    private final Mesh mesh = new Mesh();
    private final StringBuilder text = new StringBuilder(INITIAL_CAPACITY);
    private final ColorRGBA color = new ColorRGBA(ColorRGBA.White);
    private FloatBuffer positions;
    private FloatBuffer texCoords;
    private FloatBuffer colors;
    private ShortBuffer indices;
    private int capacity;
    private int glyphs;
    private int lineCount = 1;
    private float size;

    /**
     * Create an empty text at the font's rendered size.
     *
     * @param font the font, with one page (not null)
     * @param color the text's colour (not null, copied)
     */
    public HudText(BitmapFont font, ColorRGBA color) {
        super("HudText");
        if (font.getPageSize() != 1) {
            throw new IllegalArgumentException("HudText draws fonts of one page, but this one"
                    + " has " + font.getPageSize());
        }
        this.font = font;
        this.charSet = font.getCharSet();
        this.size = charSet.getRenderedSize();
        this.color.set(color);
        allocate(INITIAL_CAPACITY);
        geometry = new Geometry("HudText glyphs", mesh);
        geometry.setMaterial(font.getPage(0));
        attachChild(geometry);
        rebuild();
    }

    /**
     * Show a text, if it differs from the one shown: its glyphs are laid out again into the
     * same buffers. Allocates nothing unless the text is longer than any before. A text
     * longer than {@link #MAX_GLYPHS} characters (more glyphs than 16-bit indices can name)
     * shows its first {@link #MAX_GLYPHS}, rather than fail on the render thread.
     *
     * @param newText the text, lines separated by '\n' (not null, not modified)
     * @return true if the text shown changed
     */
    public boolean setText(CharSequence newText) {
        int length = Math.min(newText.length(), MAX_GLYPHS);
        if (isShown(newText, length)) {
            return false;
        }
        text.setLength(0);
        text.append(newText, 0, length);
        rebuild();
        return true;
    }

    /**
     * Access the text shown, without copying it.
     *
     * @return the live text (not null, do not modify)
     */
    public CharSequence getChars() {
        return text;
    }

    /**
     * Return a copy of the text shown (allocates: for tests and rare events).
     *
     * @return a new String (not null)
     */
    public String getText() {
        return text.toString();
    }

    /**
     * Access the font.
     *
     * @return the font (not null)
     */
    public BitmapFont getFont() {
        return font;
    }

    /**
     * Set the text size: the height of a line is the font's line height times
     * {@code size / renderedSize}, as with {@code BitmapText.setSize}.
     *
     * @param newSize the size (in the parent's units, pixels on the GUI node, finite, &gt;0)
     */
    public void setSize(float newSize) {
        if (!(newSize > 0f) || Float.isInfinite(newSize)) {
            throw new IllegalArgumentException("text size must be finite and > 0, but was "
                    + newSize);
        }
        size = newSize;
        float scale = size / charSet.getRenderedSize();
        geometry.setLocalScale(scale, scale, 1f);
    }

    /**
     * Return the text size.
     *
     * @return the size (&gt;0)
     */
    public float getSize() {
        return size;
    }

    /**
     * Return the distance between two baselines at the current size.
     *
     * @return the height (in the parent's units, &gt;0)
     */
    public float getLineHeight() {
        return charSet.getLineHeight() * size / charSet.getRenderedSize();
    }

    /**
     * Count the lines: one more than the text has line breaks.
     *
     * @return the count (&ge;1)
     */
    public int getLineCount() {
        return lineCount;
    }

    /**
     * Count the glyphs drawn (characters with a visible glyph in the font).
     *
     * @return the count (&ge;0)
     */
    public int countGlyphs() {
        return glyphs;
    }

    /**
     * Set the text's colour; rewrites the colour buffer, allocating nothing.
     *
     * @param newColor the colour (not null, copied)
     */
    public void setColor(ColorRGBA newColor) {
        color.set(newColor);
        fillColors();
    }

    /** @return true if the first length characters of a text are the text shown */
    private boolean isShown(CharSequence newText, int length) {
        if (text.length() != length) {
            return false;
        }
        for (int i = 0; i < length; ++i) {
            if (text.charAt(i) != newText.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** Lay the glyphs out into the buffers, as BitmapText does, in the font's own units. */
    private void rebuild() {
        int needed = text.length();
        if (needed > capacity) {
            allocate(Math.min(MAX_GLYPHS, Math.max(needed, 2 * capacity)));
        }
        positions.clear();
        texCoords.clear();
        float width = charSet.getWidth();
        float height = charSet.getHeight();
        float lineHeight = charSet.getLineHeight();
        float lineY = 0f;
        float nextX = 0f;
        boolean lineStart = true;
        BitmapCharacter previous = null;
        int lines = 1;
        int drawn = 0;
        for (int i = 0; i < text.length(); ++i) {
            char c = text.charAt(i);
            if (c == '\n') {
                lineY -= lineHeight;
                nextX = 0f;
                lineStart = true;
                previous = null;
                ++lines;
                continue;
            }
            BitmapCharacter glyph = charSet.getCharacter(c);
            if (glyph == null) {
                // No glyph in the font (the font tests rule that out for HUD text): nothing.
                previous = null;
                lineStart = false;
                continue;
            }
            float x0;
            if (lineStart) {
                // A line's first glyph starts at 0, not shifted by its offset.
                x0 = 0f;
                nextX = glyph.getXAdvance() - glyph.getXOffset();
            } else {
                x0 = nextX + glyph.getXOffset();
                nextX += glyph.getXAdvance();
            }
            if (previous != null) {
                float kerning = previous.getKerning(c);
                x0 += kerning;
                nextX += kerning;
            }
            lineStart = false;
            previous = glyph;
            if (c == ' ' || glyph.getWidth() == 0 || glyph.getHeight() == 0) {
                continue;
            }
            float y0 = lineY - glyph.getYOffset();
            float x1 = x0 + glyph.getWidth();
            float y1 = y0 - glyph.getHeight();
            float u0 = glyph.getX() / width;
            float u1 = u0 + glyph.getWidth() / width;
            float v0 = 1f - glyph.getY() / height;
            float v1 = v0 - glyph.getHeight() / height;
            positions.put(x0).put(y0).put(0f).put(x0).put(y1).put(0f)
                    .put(x1).put(y1).put(0f).put(x1).put(y0).put(0f);
            texCoords.put(u0).put(v0).put(u0).put(v1).put(u1).put(v1).put(u1).put(v0);
            ++drawn;
        }
        // The rest of the capacity: every corner at the origin, a glyph of no area.
        while (positions.hasRemaining()) {
            positions.put(0f);
        }
        while (texCoords.hasRemaining()) {
            texCoords.put(0f);
        }
        positions.flip();
        texCoords.flip();
        glyphs = drawn;
        lineCount = lines;
        mesh.getBuffer(VertexBuffer.Type.Position).setUpdateNeeded();
        mesh.getBuffer(VertexBuffer.Type.TexCoord).setUpdateNeeded();
        mesh.updateBound();
        if (geometry != null) {
            geometry.updateModelBound();
        }
    }

    /** Make buffers for a number of glyphs (allocates), indexed once and for all. */
    private void allocate(int glyphCapacity) {
        capacity = glyphCapacity;
        int vertices = capacity * VERTICES_PER_GLYPH;
        positions = BufferUtils.createFloatBuffer(vertices * POSITION_COMPONENTS);
        texCoords = BufferUtils.createFloatBuffer(vertices * TEX_COORD_COMPONENTS);
        colors = BufferUtils.createFloatBuffer(vertices * COLOR_COMPONENTS);
        indices = BufferUtils.createShortBuffer(capacity * INDICES_PER_GLYPH);
        for (int i = 0; i < capacity; ++i) {
            int corner = i * VERTICES_PER_GLYPH;
            // Two counter-clockwise triangles: top-left, bottom-left, bottom-right, top-right.
            indices.put((short) corner).put((short) (corner + 1)).put((short) (corner + 2))
                    .put((short) corner).put((short) (corner + 2)).put((short) (corner + 3));
        }
        indices.flip();
        // New buffers, not new data in the old ones: those may have been sent to the GPU.
        mesh.clearBuffer(VertexBuffer.Type.Position);
        mesh.clearBuffer(VertexBuffer.Type.TexCoord);
        mesh.clearBuffer(VertexBuffer.Type.Color);
        mesh.clearBuffer(VertexBuffer.Type.Index);
        mesh.setBuffer(VertexBuffer.Type.Position, POSITION_COMPONENTS, positions);
        mesh.setBuffer(VertexBuffer.Type.TexCoord, TEX_COORD_COMPONENTS, texCoords);
        mesh.setBuffer(VertexBuffer.Type.Color, COLOR_COMPONENTS, colors);
        mesh.setBuffer(VertexBuffer.Type.Index, 3, indices);
        fillColors();
        mesh.updateCounts();
    }

    private void fillColors() {
        colors.clear();
        while (colors.hasRemaining()) {
            colors.put(color.r).put(color.g).put(color.b).put(color.a);
        }
        colors.flip();
        mesh.getBuffer(VertexBuffer.Type.Color).setUpdateNeeded();
    }
}
