package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The impulse labels' layout: labels placed never overlap each other or an obstacle and stay
 * inside the area; a label goes short, then hidden, only as room runs out; and an arrow's
 * tip stays above the ground band.
 */
class CalloutLayoutTest {

    private static final ScreenRect AREA = new ScreenRect(0f, 100f, 1280f, 500f);

    /**
     * Random crowds of spheres and arrows, as many labels as the demo's pool holds: every
     * label placed is inside the area, covers no obstacle and no other label.
     */
    @Test
    void placedLabelsAreDisjointFromEachOtherAndTheObstacles() {
        Random random = new Random(12);
        for (int trial = 0; trial < 500; ++trial) {
            CalloutLayout layout = new CalloutLayout(40);
            layout.begin(AREA);
            List<ScreenRect> obstacles = new ArrayList<>();
            for (int i = 0; i < 12; ++i) {
                ScreenRect sphere = new ScreenRect(1280f * random.nextFloat(),
                        100f + 500f * random.nextFloat(), 28f, 28f);
                obstacles.add(sphere);
                layout.addObstacle(sphere);
            }
            List<ScreenRect> placed = new ArrayList<>();
            for (int label = 0; label < 16; ++label) {
                ScreenRect place = new ScreenRect();
                float full = 40f + 120f * random.nextFloat();
                int form = layout.place(1280f * random.nextFloat(),
                        100f + 500f * random.nextFloat(), random.nextFloat() - 0.5f,
                        random.nextFloat() - 0.5f, full, 0.4f * full, 18f, 5f, place);
                if (form == CalloutLayout.HIDDEN) {
                    assertTrue(place.isEmpty(), "a hidden label has no place");
                    continue;
                }
                assertEquals(form == CalloutLayout.FULL ? full : 0.4f * full,
                        place.getWidth(), 1e-3f, "the form's width");
                assertTrue(AREA.contains(place), "trial " + trial + ": " + place + " outside");
                for (ScreenRect obstacle : obstacles) {
                    assertFalse(obstacle.intersects(place), "trial " + trial + ": " + place
                            + " covers " + obstacle);
                }
                for (ScreenRect other : placed) {
                    assertFalse(other.intersects(place), "trial " + trial + ": " + place
                            + " covers label " + other);
                }
                placed.add(place);
            }
        }
    }

    /**
     * A trail along the arrow's line (a head-on ball's path): the label does not go beyond
     * the tip on the line, where it lay over the trail (issue 29 §3), but beside it, clear of
     * every point by the trail's drawn half width; a trail hemming in every place hides it.
     */
    @Test
    void aLabelKeepsOffTheTrailPointsByTheirHalfWidth() {
        CalloutLayout layout = new CalloutLayout(8);
        ScreenRect place = new ScreenRect();
        float[] xs = new float[200];
        float[] ys = new float[200];
        for (int i = 0; i < 100; ++i) {
            // A horizontal trail through the tip's height, a point every 5 px.
            xs[i] = 300f + 5f * i;
            ys[i] = 300f;
        }
        float half = 3f;
        layout.begin(AREA);
        layout.setTrailPoints(xs, ys, 100, half);
        assertEquals(CalloutLayout.FULL, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertTrue(place.getY() > 300f + half || place.getTop() < 300f - half,
                place + " lies over the trail at y = 300 (half width " + half + " px)");
        // Without the points the same label sat on the line (x 504, y 290..310).
        layout.begin(AREA);
        layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f, place);
        assertEquals(290f, place.getY(), 0f, "begin forgot the points");
        // A second trail across every place within reach: the label is hidden.
        for (int i = 0; i < 100; ++i) {
            xs[100 + i] = 500f;
            ys[100 + i] = 200f + 2f * i;
        }
        layout.begin(AREA);
        layout.setTrailPoints(xs, ys, 200, 200f);
        assertEquals(CalloutLayout.HIDDEN, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertThrows(IllegalArgumentException.class,
                () -> layout.setTrailPoints(xs, ys, 201, half));
        assertThrows(IllegalArgumentException.class,
                () -> layout.setTrailPoints(xs, ys, 10, Float.NaN));
    }

    /**
     * An arrow pointing right with room: its label beyond the tip, the gap away, centred on
     * the arrow's line. A sphere there: the label beside the line instead. Room only for the
     * short form: short. No room at all: hidden.
     */
    @Test
    void aLabelGoesBeyondTheTipThenBesideThenShortThenNowhere() {
        CalloutLayout layout = new CalloutLayout(8);
        ScreenRect place = new ScreenRect();
        layout.begin(AREA);
        assertEquals(CalloutLayout.FULL, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertEquals(504f, place.getX(), 0f);
        assertEquals(290f, place.getY(), 0f);

        layout.begin(AREA);
        layout.addObstacle(520f, 292f, 20f, 12f);
        assertEquals(CalloutLayout.FULL, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertEquals(304f, place.getY(), 0f, "above the line, a gap off it");

        // Walled in 40 px beyond the tip, above and below the line: only 30 px fits.
        layout.begin(new ScreenRect(0f, 280f, 545f, 40f));
        assertEquals(CalloutLayout.SHORT, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertEquals(30f, place.getWidth(), 0f);

        layout.begin(new ScreenRect(0f, 280f, 520f, 40f));
        assertEquals(CalloutLayout.HIDDEN, layout.place(500f, 300f, 1f, 0f, 80f, 30f, 20f, 4f,
                place));
        assertTrue(place.isEmpty());
    }

    /**
     * An arrow pointing down from y0 at k m per N·s, scaled by {@code lengthScale}, ends at
     * the floor or above it, and is shortened only when it would reach below.
     */
    @Test
    void anArrowsTipStaysAboveTheGroundBand() {
        Random random = new Random(7);
        float k = 0.2f;
        float floor = 0.075f;
        for (int trial = 0; trial < 10_000; ++trial) {
            float startY = floor + 3f * random.nextFloat();
            float impulseY = 20f * (random.nextFloat() - 0.5f);
            float scale = ImpulseArrows.lengthScale(startY, impulseY, k, floor);
            float tip = startY + scale * k * impulseY;
            assertTrue(scale > 0f || startY == floor, "scale " + scale);
            assertTrue(scale <= 1f, "never longer: " + scale);
            // One float division and a product of numbers below 10: a few ulps of 3 m.
            assertTrue(tip >= floor - 1e-5f, "trial " + trial + ": tip " + tip);
            if (startY + k * impulseY >= floor) {
                assertEquals(1f, scale, "shortened though it stayed above");
            } else {
                assertEquals(floor, tip, 1e-5f, "shortened more than needed");
            }
        }
    }

    @Test
    void aFullPoolIsRefusedSayingHowManyItHolds() {
        CalloutLayout layout = new CalloutLayout(1);
        layout.begin(AREA);
        layout.addObstacle(0f, 0f, 1f, 1f);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> layout.addObstacle(2f, 2f, 1f, 1f));
        assertTrue(e.getMessage().contains("1 obstacles"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new CalloutLayout(0));
    }
}
