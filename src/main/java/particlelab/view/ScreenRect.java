package particlelab.view;

/**
 * An axis-aligned rectangle on the screen, in pixels, with jME's GUI convention: x to the
 * right and y up from the window's bottom-left corner. Mutable, so that per-frame layout can
 * reuse one instead of allocating.
 */
public final class ScreenRect {

    private float x;
    private float y;
    private float width;
    private float height;

    /** Create an empty rectangle at the origin. */
    public ScreenRect() {
    }

    /**
     * Create a rectangle.
     *
     * @param x the left edge (in pixels)
     * @param y the bottom edge (in pixels)
     * @param width the width (in pixels, &ge;0)
     * @param height the height (in pixels, &ge;0)
     */
    public ScreenRect(float x, float y, float width, float height) {
        set(x, y, width, height);
    }

    /**
     * Alter every edge.
     *
     * @param newX the left edge (in pixels)
     * @param newY the bottom edge (in pixels)
     * @param newWidth the width (in pixels, &ge;0)
     * @param newHeight the height (in pixels, &ge;0)
     * @return this
     */
    public ScreenRect set(float newX, float newY, float newWidth, float newHeight) {
        x = newX;
        y = newY;
        width = Math.max(0f, newWidth);
        height = Math.max(0f, newHeight);
        return this;
    }

    /**
     * Copy another rectangle.
     *
     * @param other the rectangle to copy (not null, not modified)
     * @return this
     */
    public ScreenRect set(ScreenRect other) {
        return set(other.x, other.y, other.width, other.height);
    }

    /** @return the left edge (in pixels) */
    public float getX() {
        return x;
    }

    /** @return the bottom edge (in pixels) */
    public float getY() {
        return y;
    }

    /** @return the width (in pixels, &ge;0) */
    public float getWidth() {
        return width;
    }

    /** @return the height (in pixels, &ge;0) */
    public float getHeight() {
        return height;
    }

    /** @return the right edge (in pixels) */
    public float getRight() {
        return x + width;
    }

    /** @return the top edge (in pixels) */
    public float getTop() {
        return y + height;
    }

    /**
     * Test whether this has no area.
     *
     * @return true if the width or the height is zero
     */
    public boolean isEmpty() {
        return width <= 0f || height <= 0f;
    }

    /**
     * Test whether two rectangles share some area (touching edges do not count). An empty
     * rectangle intersects nothing.
     *
     * @param other the other rectangle (not null, not modified)
     * @return true if they overlap
     */
    public boolean intersects(ScreenRect other) {
        return !isEmpty() && !other.isEmpty() && x < other.getRight() && other.x < getRight()
                && y < other.getTop() && other.y < getTop();
    }

    /**
     * Test whether a point lies inside (edges included).
     *
     * @param pointX the point's x (in pixels)
     * @param pointY the point's y (in pixels)
     * @return true if inside
     */
    public boolean contains(float pointX, float pointY) {
        return pointX >= x && pointX <= getRight() && pointY >= y && pointY <= getTop();
    }

    /**
     * Test whether another rectangle lies wholly inside this one (edges may touch).
     *
     * @param other the other rectangle (not null, not modified)
     * @return true if inside
     */
    public boolean contains(ScreenRect other) {
        return other.x >= x && other.getRight() <= getRight() && other.y >= y
                && other.getTop() <= getTop();
    }

    @Override
    public String toString() {
        return String.format("[x %.1f..%.1f, y %.1f..%.1f]", x, getRight(), y, getTop());
    }
}
