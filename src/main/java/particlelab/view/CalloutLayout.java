package particlelab.view;

/**
 * Places the labels of arrows (the collisions demo's impulses) so that none covers another,
 * a sphere, a scene text, the HUD or a trail as drawn, in screen pixels. Each label goes along its arrow
 * beyond the tip, away from where the arrow starts: first right at the tip, then beside the
 * arrow's line there (either side), then slid further out along the arrow, a line height at
 * a time; in its full form first, then in its
 * short form (the unit or the note dropped); where neither fits it is hidden. A placed label
 * becomes an obstacle for the next, so the labels placed first (the newest) win. A fixed pool
 * of rectangles made at construction: placing allocates nothing.
 */
public final class CalloutLayout {

    /** {@link #place}'s answer: no room, the label is hidden. */
    public static final int HIDDEN = 0;
    /** {@link #place}'s answer: the short form fits. */
    public static final int SHORT = 1;
    /** {@link #place}'s answer: the full form fits. */
    public static final int FULL = 2;
    /** How many places along the arrow are tried, a line height apart. */
    private static final int SLIDES = 4;
    /** At each place: beyond it, and beside the arrow's line on either side. */
    private static final int SIDES = 3;

    /** The pool: what labels must not cover this frame, the first {@link #obstacleCount}. */
    private final ScreenRect[] obstacles;
    /** How many of the pool hold an obstacle. */
    private int obstacleCount;
    /** Where labels may go (in pixels). */
    private final ScreenRect bounds = new ScreenRect();
    /** Scratch: the place being tried (in pixels). */
    private final ScreenRect trial = new ScreenRect();
    /** The trail points labels keep off (pixels; the caller's arrays, not copied). */
    private float[] pointsX = new float[0];
    private float[] pointsY = new float[0];
    /** How many of the points' arrays hold points, the first ones. */
    private int pointCount;
    /** How close to a label a point counts as covered (pixels: the trail's half width). */
    private float pointClearance;

    /**
     * Create a layout with room for a number of obstacles (spheres, texts, labels placed).
     *
     * @param capacity the most obstacles one frame adds, labels placed included (&gt;0)
     */
    public CalloutLayout(int capacity) {
        if (capacity <= 0) {
            throw new IllegalArgumentException("callout capacity must be > 0, but was "
                    + capacity);
        }
        obstacles = new ScreenRect[capacity];
        for (int i = 0; i < capacity; ++i) {
            obstacles[i] = new ScreenRect();
        }
    }

    /**
     * Start a frame's layout: forget the obstacles, and keep the labels inside a rectangle.
     *
     * @param inside where labels may go (in pixels, not null, copied)
     */
    public void begin(ScreenRect inside) {
        bounds.set(inside);
        obstacleCount = 0;
        pointCount = 0;
    }

    /**
     * Give the frame's trail points, which labels keep off as they keep off the obstacles: a
     * place is taken only if no point lies within the clearance of it (a trail's ribbon and
     * step dots reach that far from their points). Call after {@link #begin}, which forgets
     * them. The arrays are not copied: leave them unchanged until the frame's labels are
     * placed.
     *
     * @param xs the points' x (in pixels, not null)
     * @param ys the points' y (in pixels, not null)
     * @param count how many points, the first of each array (&ge;0, within both arrays)
     * @param clearance how close to a label a point counts as covered (in pixels, &ge;0)
     */
    public void setTrailPoints(float[] xs, float[] ys, int count, float clearance) {
        if (count < 0 || count > xs.length || count > ys.length || !(clearance >= 0f)
                || clearance == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("trail points: count " + count + " must be"
                    + " within the arrays (" + xs.length + ", " + ys.length + ") and the"
                    + " clearance " + clearance + " px finite and >= 0");
        }
        pointsX = xs;
        pointsY = ys;
        pointCount = count;
        pointClearance = clearance;
    }

    /**
     * Add something a label must not cover; an empty rectangle is ignored.
     *
     * @param obstacle its rectangle (in pixels, not null, copied)
     */
    public void addObstacle(ScreenRect obstacle) {
        addObstacle(obstacle.getX(), obstacle.getY(), obstacle.getWidth(),
                obstacle.getHeight());
    }

    /**
     * Add something a label must not cover; an empty rectangle is ignored.
     *
     * @param x its left (in pixels)
     * @param y its bottom (in pixels)
     * @param width its width (in pixels)
     * @param height its height (in pixels)
     */
    public void addObstacle(float x, float y, float width, float height) {
        if (obstacleCount == obstacles.length) {
            throw new IllegalStateException("callout layout holds " + obstacles.length
                    + " obstacles, no more");
        }
        if (width > 0f && height > 0f) {
            obstacles[obstacleCount++].set(x, y, width, height);
        }
    }

    /**
     * Place one arrow's label beyond its tip and add it as an obstacle.
     *
     * @param tipX the arrow's tip (in pixels)
     * @param tipY the arrow's tip (in pixels)
     * @param directionX the arrow's direction, start to tip (any length; zero: to the right)
     * @param directionY the arrow's direction's y
     * @param fullWidth the full label's width (in pixels, &gt;0)
     * @param shortWidth the short label's width (in pixels, &gt;0, &le; fullWidth)
     * @param height the label's height (in pixels, &gt;0)
     * @param gap the room between the tip and the label (in pixels, &ge;0)
     * @param storeResult storage for the label's rectangle (not null, modified; empty when
     *     hidden)
     * @return {@link #FULL}, {@link #SHORT} or {@link #HIDDEN}
     */
    public int place(float tipX, float tipY, float directionX, float directionY,
            float fullWidth, float shortWidth, float height, float gap,
            ScreenRect storeResult) {
        float length = (float) Math.sqrt(directionX * directionX + directionY * directionY);
        float ux = length > 0f ? directionX / length : 1f;
        float uy = length > 0f ? directionY / length : 0f;
        for (int form = FULL; form >= SHORT; --form) {
            float width = form == FULL ? fullWidth : shortWidth;
            for (int slide = 0; slide < SLIDES; ++slide) {
                float along = gap + slide * height;
                for (int side = 0; side < SIDES; ++side) {
                    put(tipX + along * ux, tipY + along * uy, ux, uy, width, height, gap,
                            side);
                    if (isFree(trial)) {
                        storeResult.set(trial);
                        addObstacle(trial);
                        return form;
                    }
                }
            }
        }
        storeResult.set(0f, 0f, 0f, 0f);
        return HIDDEN;
    }

    /**
     * Put the trial rectangle at a point on the arrow's line beyond the tip: side 0 beyond
     * the point, its side facing the arrow at the point and centred on the arrow's line (a
     * mostly horizontal arrow's label beside it, a mostly vertical one's above or below);
     * sides 1 and 2 beside the line there, a gap off it, one way and the other.
     */
    private void put(float pointX, float pointY, float ux, float uy, float width,
            float height, float gap, int side) {
        boolean horizontal = Math.abs(ux) >= Math.abs(uy);
        if (side == 0 && horizontal) {
            float x = ux >= 0f ? pointX : pointX - width;
            trial.set(x, pointY - height / 2f, width, height);
        } else if (side == 0) {
            float y = uy >= 0f ? pointY : pointY - height;
            trial.set(pointX - width / 2f, y, width, height);
        } else if (horizontal) {
            // Above or below the line, starting at the point, reaching away from the start.
            float x = ux >= 0f ? pointX : pointX - width;
            float y = side == 1 ? pointY + gap : pointY - gap - height;
            trial.set(x, y, width, height);
        } else {
            // Right or left of the line, starting at the point, reaching away from the start.
            float x = side == 1 ? pointX + gap : pointX - gap - width;
            float y = uy >= 0f ? pointY : pointY - height;
            trial.set(x, y, width, height);
        }
    }

    private boolean isFree(ScreenRect place) {
        if (!bounds.contains(place)) {
            return false;
        }
        for (int i = 0; i < obstacleCount; ++i) {
            if (obstacles[i].intersects(place)) {
                return false;
            }
        }
        float left = place.getX() - pointClearance;
        float right = place.getRight() + pointClearance;
        float bottom = place.getY() - pointClearance;
        float top = place.getTop() + pointClearance;
        for (int i = 0; i < pointCount; ++i) {
            if (pointsX[i] >= left && pointsX[i] <= right && pointsY[i] >= bottom
                    && pointsY[i] <= top) {
                return false;
            }
        }
        return true;
    }
}
