package particlelab.view;

import com.jme3.font.BitmapFont;

/**
 * Measures text as jME will draw it, so that a layout can be computed without rendering: the
 * width of a line and the height of one line, for a text size.
 */
public interface TextMeasure {

    /**
     * Measure the widest line of a text.
     *
     * @param text the text, lines separated by '\n' (not null, not modified)
     * @param size the text size (in pixels, &gt;0)
     * @return the width (in pixels, &ge;0)
     */
    float width(CharSequence text, float size);

    /**
     * Measure the height of one line: the distance between two baselines.
     *
     * @param size the text size (in pixels, &gt;0)
     * @return the height (in pixels, &gt;0)
     */
    float lineHeight(float size);

    /**
     * Measure with a jME bitmap font, exactly as {@code BitmapText.getLineWidth} does.
     *
     * @param font the font (not null)
     * @return a measure (not null)
     */
    static TextMeasure of(BitmapFont font) {
        float renderedSize = font.getCharSet().getRenderedSize();
        float lineHeight = font.getCharSet().getLineHeight();
        return new TextMeasure() {
            @Override
            public float width(CharSequence text, float size) {
                return font.getLineWidth(text) * size / renderedSize;
            }

            @Override
            public float lineHeight(float size) {
                return lineHeight * size / renderedSize;
            }
        };
    }
}
