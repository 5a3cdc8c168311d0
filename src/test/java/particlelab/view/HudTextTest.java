package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.system.JmeSystem;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * The allocation-free HUD text draws every glyph where jME's BitmapText draws it, from the same
 * part of the font's texture, and changing its text allocates nothing. No display needed: the
 * font is loaded by a desktop asset manager and the meshes are compared as data.
 */
class HudTextTest {

    /** A HUD's kinds of text: Greek, superscripts, maths signs, kerned pairs, blank lines. */
    private static final String[] TEXTS = {
        "",
        "Drag",
        "t = 1.25 s   |V| = 13.4 m/s   a = 9.81 m/s²\n",
        "λ = 0.10 N·s/m   ω = 2π·f   Δt ≈ 0.0167 s   θ → 45°\n\nAVATAR Yo To Wa\n",
        "  indented\n    continuation (after a wrap)\n≤ ≥ ≠ ∞ √ ∑ ∂ ∇ − ± × ÷ ½ ¼\n",
        "\n\ntrailing lines\n\n",
    };
    private static BitmapFont font;

    @BeforeAll
    static void loadFont() {
        AssetManager assets = JmeSystem.newAssetManager(
                JmeSystem.class.getResource("/com/jme3/asset/Desktop.cfg"));
        font = HudFont.load(assets);
    }

    @Test
    void glyphsGoWhereBitmapTextPutsThem() {
        float[] sizes = {font.getCharSet().getRenderedSize(), 17f, 31.5f};
        for (float size : sizes) {
            for (String text : TEXTS) {
                BitmapText reference = new BitmapText(font);
                reference.setSize(size);
                reference.setText(text);
                HudText shown = new HudText(font, ColorRGBA.White);
                shown.setSize(size);
                shown.setText(text);
                String what = "'" + text + "' at " + size;
                List<float[]> expected = referenceQuads(reference);
                List<float[]> actual = quads(shown);
                assertEquals(expected.size(), actual.size(), what + ": glyphs");
                assertEquals(expected.size(), shown.countGlyphs(), what);
                for (int i = 0; i < expected.size(); ++i) {
                    for (int k = 0; k < expected.get(i).length; ++k) {
                        // Positions: jME scales each corner, HudText scales the mesh; the two
                        // float products differ by round-off (< 1e-4 px at these sizes).
                        // Texture coordinates are the same quotients of integers.
                        assertEquals(expected.get(i)[k], actual.get(i)[k], 1e-4f,
                                what + ": glyph " + i + " value " + k);
                    }
                }
                if (!text.isEmpty()) {
                    assertEquals(reference.getLineCount(), shown.getLineCount(), what);
                }
                assertEquals(reference.getLineHeight(), shown.getLineHeight(), 1e-5f, what);
            }
        }
    }

    @Test
    void changingTheTextAllocatesNothingOnceTheBuffersAreLargeEnough() {
        HudText shown = new HudText(font, ColorRGBA.White);
        StringBuilder text = new StringBuilder(256);
        int[] frame = {0};
        shown.setText(TEXTS[3] + TEXTS[2] + TEXTS[4]);
        Runnable refreshes = () -> {
            for (int i = 0; i < 100; ++i) {
                text.setLength(0);
                text.append("t = ");
                TextFormat.appendFixed(text, 0.0167 * ++frame[0], 2).append(" s  λ²\n");
                TextFormat.appendFixed(text, 1.0 / frame[0], 4).append(" m/s²\n");
                shown.setText(text);
            }
        };
        Allocations.assertAllocatesNothing("100 new texts", refreshes);
        assertTrue(shown.getText().endsWith(" m/s²\n"), shown.getText());
        assertFalse(shown.setText(shown.getText()), "the same text is no change");
    }

    @Test
    void aTextLongerThanAnyBeforeGrowsTheBuffersAndStillDrawsEveryGlyph() {
        HudText shown = new HudText(font, ColorRGBA.White);
        StringBuilder longText = new StringBuilder();
        while (longText.length() < 1000) {
            longText.append("0123456789 ");
        }
        shown.setText(longText);
        BitmapText reference = new BitmapText(font);
        reference.setText(longText);
        assertEquals(referenceQuads(reference).size(), shown.countGlyphs());
        shown.setText("short");
        assertEquals(5, shown.countGlyphs());
    }

    /** The drawn quads of a HudText: eight positions (x, y per corner) and eight texCoords. */
    private static List<float[]> quads(HudText text) {
        Geometry geometry = (Geometry) text.getChild(0);
        Vector3f scale = geometry.getLocalScale();
        List<float[]> all = readQuads(geometry.getMesh(), scale.x);
        List<float[]> drawn = new ArrayList<>();
        for (float[] quad : all) {
            if (quad[0] != quad[4] || quad[1] != quad[3]) {
                drawn.add(quad);
            }
        }
        return drawn;
    }

    /** The quads of BitmapText's one page, its blank glyphs (spaces) left out. */
    private static List<float[]> referenceQuads(BitmapText text) {
        text.updateLogicalState(0f);
        List<float[]> drawn = new ArrayList<>();
        if (text.getQuantity() == 0) {
            return drawn;
        }
        Geometry page = (Geometry) text.getChild(0);
        for (float[] quad : readQuads(page.getMesh(), 1f)) {
            if (quad[0] != quad[4] && quad[1] != quad[3]) {
                drawn.add(quad);
            }
        }
        return drawn;
    }

    private static List<float[]> readQuads(Mesh mesh, float scale) {
        FloatBuffer positions = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position)
                .getData();
        FloatBuffer texCoords = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord)
                .getData();
        ShortBuffer indices = (ShortBuffer) mesh.getBuffer(VertexBuffer.Type.Index).getData();
        List<float[]> quads = new ArrayList<>();
        for (int i = 0; i + 5 < indices.limit(); i += 6) {
            float[] quad = new float[16];
            int[] corners = {indices.get(i), indices.get(i + 1), indices.get(i + 2),
                indices.get(i + 5)};
            for (int c = 0; c < 4; ++c) {
                quad[2 * c] = positions.get(3 * corners[c]) * scale;
                quad[2 * c + 1] = positions.get(3 * corners[c] + 1) * scale;
                quad[8 + 2 * c] = texCoords.get(2 * corners[c]);
                quad[8 + 2 * c + 1] = texCoords.get(2 * corners[c] + 1);
            }
            quads.add(quad);
        }
        return quads;
    }
}
