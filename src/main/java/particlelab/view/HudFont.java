package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.texture.Texture;

/**
 * The font of every text the app draws: DejaVu Sans Condensed (narrow, so long HUD lines fit)
 * rendered at {@value FontGenerator#RENDER_SIZE} px into {@code assets/Fonts} by
 * {@link FontGenerator}. jME's own {@code Default.fnt} has no {@code λ} and only blank
 * placeholders for {@code ²} and {@code ·} ("m/s²" came out as "m/s "); this one has every
 * character of {@link #CHARACTERS}.
 */
public final class HudFont {

    /** The generated files' name, without extension. */
    public static final String BASE_NAME = "DejaVuSansCondensed-48";
    /** The font's asset path (the top-level {@code assets/} folder is on the classpath). */
    public static final String ASSET = "Fonts/" + BASE_NAME + ".fnt";
    /**
     * Every character the font has: printable ASCII, Latin-1, Greek, and the arrows, dashes,
     * quotes and maths signs a physics HUD prints.
     */
    public static final String CHARACTERS = range(0x20, 0x7E) + range(0xA0, 0xFF)
            + range(0x391, 0x3A1) + range(0x3A3, 0x3A9) + range(0x3B1, 0x3C9)
            + "\u2013\u2014\u2018\u2019\u201C\u201D\u2022\u2026\u2032\u2033"
            + "\u2070\u2071\u2074\u2075\u2076\u2077\u2078\u2079\u207A\u207B"
            + "\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089"
            + "\u2190\u2191\u2192\u2193\u2194\u21BA\u21BB"
            + "\u2202\u2206\u2207\u2211\u2212\u2219\u221A\u221D\u221E\u2248\u2260\u2261"
            + "\u2264\u2265\u22C5\u25B2\u25B6\u25BC\u25C0\u25CF\u2713\u2717";

    private HudFont() {
    }

    /**
     * Load the font, with mipmapped minification, so text drawn smaller than the rendered size
     * stays smooth.
     *
     * @param assetManager the application's asset manager (not null)
     * @return the font (not null)
     */
    public static BitmapFont load(AssetManager assetManager) {
        BitmapFont font = assetManager.loadFont(ASSET);
        for (int i = 0; i < font.getPageSize(); ++i) {
            Material page = font.getPage(i);
            Texture texture = page.getTextureParam("ColorMap").getTextureValue();
            texture.setMinFilter(Texture.MinFilter.Trilinear);
        }
        return font;
    }

    private static String range(int first, int last) {
        StringBuilder text = new StringBuilder();
        for (int c = first; c <= last; ++c) {
            if (c != 0xAD) {
                text.append((char) c);
            }
        }
        return text.toString();
    }
}
