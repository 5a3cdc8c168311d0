package particlelab.view;

/**
 * The places a moving particle's label may take around its sphere, in order of preference:
 * above right, right, above left, left, above, below right, below left, below, and the same
 * again twice, farther out. A layout scores each place against what it must not cover and
 * keeps the best; the slots themselves are pure arithmetic in pixels and allocate nothing.
 */
public final class LabelSlots {

    /** Directions per ring. */
    public static final int DIRECTIONS = 8;
    /** Rings of slots, each farther from the sphere. */
    public static final int RINGS = 3;
    /** Every slot. */
    public static final int COUNT = DIRECTIONS * RINGS;
    /** The distance between rings (in label heights). */
    private static final float RING_STEP = 1.15f;
    /** The gap between the sphere and the nearest ring (in label heights). */
    private static final float GAP = 0.15f;

    private LabelSlots() {
    }

    /**
     * Compute one slot's rectangle.
     *
     * @param slot which slot (0 to {@link #COUNT} - 1)
     * @param centreX the sphere's centre on the screen (in pixels)
     * @param centreY the sphere's centre on the screen (in pixels)
     * @param radius the sphere's radius on the screen (in pixels, &ge;0)
     * @param width the label's width (in pixels)
     * @param height the label's height (in pixels)
     * @param storeResult storage for the rectangle (not null, modified)
     * @return storeResult
     */
    public static ScreenRect rect(int slot, float centreX, float centreY, float radius,
            float width, float height, ScreenRect storeResult) {
        int ring = slot / DIRECTIONS;
        float reach = radius + height * (GAP + RING_STEP * ring);
        float side = 0.5f * radius;
        switch (slot % DIRECTIONS) {
            case 0:
                return storeResult.set(centreX + side, centreY + reach, width, height);
            case 1:
                return storeResult.set(centreX + reach, centreY - height / 2f, width, height);
            case 2:
                return storeResult.set(centreX - side - width, centreY + reach, width, height);
            case 3:
                return storeResult.set(centreX - reach - width, centreY - height / 2f, width,
                        height);
            case 4:
                return storeResult.set(centreX - width / 2f, centreY + reach, width, height);
            case 5:
                return storeResult.set(centreX + side, centreY - reach - height, width, height);
            case 6:
                return storeResult.set(centreX - side - width, centreY - reach - height, width,
                        height);
            default:
                return storeResult.set(centreX - width / 2f, centreY - reach - height, width,
                        height);
        }
    }

    /**
     * Return how far any slot's rectangle reaches from the sphere's centre, in x or y.
     *
     * @param radius the sphere's radius on the screen (in pixels, &ge;0)
     * @param width the label's width (in pixels)
     * @param height the label's height (in pixels)
     * @return the reach (in pixels)
     */
    public static float extent(float radius, float width, float height) {
        return radius + height * (GAP + RING_STEP * (RINGS - 1) + 1f) + width;
    }

    /**
     * Return the ring a slot belongs to.
     *
     * @param slot which slot (0 to {@link #COUNT} - 1)
     * @return 0 for the nearest ring
     */
    public static int ring(int slot) {
        return slot / DIRECTIONS;
    }
}
