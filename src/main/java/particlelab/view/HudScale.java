package particlelab.view;

/**
 * The HUD scale a window gets: the one that suits its size ({@link HudLayout#scaleFor}, 1 at
 * 1280x720) times a factor the user chooses for a projector ({@code --ui-scale}, and the HUD
 * scale keys), kept between {@value #MIN_SCALE} and {@link HudLayout#MAX_SCALE}.
 */
public final class HudScale {

    /** The user's factor's range, and what one press of a HUD scale key adds or takes. */
    public static final float MIN_FACTOR = 0.5f;
    public static final float MAX_FACTOR = 2f;
    public static final float FACTOR_STEP = 0.25f;
    /** The smallest scale a factor below 1 reaches (text 10.5 px high). */
    public static final float MIN_SCALE = 0.5f;

    /** The least share of the window's height a layout leaves to the scene. */
    public static final float MIN_SCENE_SHARE = HudLayout.MIN_SCENE_SHARE;
    /** What each try multiplies the scale by while HUD lines would be hidden. */
    private static final float SHRINK = 0.9f;

    private HudScale() {
    }

    /**
     * Lay a HUD out for a window. First the scale that suits the window is found: the one
     * {@link HudLayout#scaleFor} gives, smaller while the window cannot hold every HUD line
     * with {@value #MIN_SCENE_SHARE} of its height left to the scene ({@link
     * HudLayout#isTooSmall()}: a small window), down to {@value #MIN_SCALE}. Then the user's
     * factor multiplies it, and nothing shrinks it again: a larger factor always gives larger
     * text (the projector's control works one way), and where the window cannot hold every
     * line at that size, the layout hides lines (see {@link HudLayout}). The body's band
     * keeps the most lines it has needed so far, except when asked afresh, while shrinking
     * and at a factor other than 1: then it is sized for the text as it is. Where lines are
     * hidden and the text is smaller than the factor asked, the footer says both factors
     * ("text x2.0 reduced to x1.3: window too small ..."), relative to the scale that suits
     * the window.
     *
     * @param hud the HUD (not null, modified)
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param factor the user's factor (from {@value #MIN_FACTOR} to {@value #MAX_FACTOR})
     * @param afresh true to size the body's band for the body as it is (the size or the
     *     factor changed: the lines the old width or text size needed mean nothing now)
     * @return the scale used
     */
    public static float layOut(HudView hud, int width, int height, float factor,
            boolean afresh) {
        checkFactor(factor, "HUD scale factor");
        // The footer of a window too small names the factor asked for and the one it got.
        hud.getLayout().setUserFactor(factor);
        float suits = of(width, height, 1f);
        if (afresh || factor != 1f) {
            hud.layOutAfresh(width, height, suits);
        } else {
            hud.layOut(width, height, suits);
        }
        while (hud.getLayout().isTooSmall() && suits > MIN_SCALE) {
            suits = Math.max(MIN_SCALE, SHRINK * suits);
            hud.layOutAfresh(width, height, suits);
        }
        if (factor == 1f) {
            return suits;
        }
        float scale = clamp(suits * factor);
        hud.layOutAfresh(width, height, scale);
        return scale;
    }

    /**
     * Return the HUD scale for a window and a user's factor.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param factor the user's factor (from {@value #MIN_FACTOR} to {@value #MAX_FACTOR})
     * @return the scale (&gt;0)
     */
    public static float of(float width, float height, float factor) {
        checkFactor(factor, "HUD scale factor");
        return clamp(HudLayout.scaleFor(width, height) * factor);
    }

    /**
     * Step a factor up or down by {@value #FACTOR_STEP}, within its range.
     *
     * @param factor the factor now (within range)
     * @param steps how many steps (positive: larger text)
     * @return the new factor
     */
    public static float step(float factor, int steps) {
        float next = Math.round((factor + steps * FACTOR_STEP) / FACTOR_STEP) * FACTOR_STEP;
        return Math.max(MIN_FACTOR, Math.min(MAX_FACTOR, next));
    }

    /**
     * Refuse a factor out of range.
     *
     * @param factor the factor
     * @param what what it is called where it came from, for the message (not null)
     * @throws IllegalArgumentException if not from {@value #MIN_FACTOR} to
     *     {@value #MAX_FACTOR}
     */
    public static void checkFactor(float factor, String what) {
        if (!(factor >= MIN_FACTOR && factor <= MAX_FACTOR)) {
            throw new IllegalArgumentException(what + " must be from " + MIN_FACTOR + " to "
                    + MAX_FACTOR + ", but was " + factor);
        }
    }

    /** Keep a scale from {@value #MIN_SCALE} to {@link HudLayout#MAX_SCALE}. */
    private static float clamp(float scale) {
        return Math.max(MIN_SCALE, Math.min(HudLayout.MAX_SCALE, scale));
    }
}
