package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.view.PointCloudMesh;
import particlelab.world.Fountain;
import particlelab.world.StateSlab;

/**
 * The fountain's mesh update ({@link FountainPoints}: the positions of the particles in
 * flight in bulk, the colours that changed) leaves the mesh's buffers byte for byte as the
 * update before issue 23 did (every slot, one put per float and per colour byte, written
 * below as the reference), the positions in the planar layout (one buffer an axis), through a
 * seeded run with frames of zero, one and several steps, a reset and a state read back. No
 * window: the mesh is built without a material.
 */
class FountainPointsTest {

    private static final float H = 1f / 60f;
    private static final int POOL = 3000;
    private static final float WATER_BRIGHTNESS = 0.15f;
    /** x, y, z: one position buffer each. */
    private static final int AXES = 3;

    @Test
    void theBuffersHoldWhatACopyOfEverySlotGives() {
        Fountain fountain = new Fountain(POOL);
        PointCloudMesh mesh = new PointCloudMesh(POOL, Fountain.REGION_TOP);
        FountainPoints points = new FountainPoints(mesh, WATER_BRIGHTNESS);
        FloatBuffer[] expectedPositions = new FloatBuffer[AXES];
        for (int axis = 0; axis < AXES; ++axis) {
            expectedPositions[axis] = ByteBuffer.allocateDirect(4 * POOL)
                    .order(ByteOrder.nativeOrder()).asFloatBuffer();
        }
        ByteBuffer expectedColours = ByteBuffer.allocateDirect(4 * POOL);
        int[] saved = new int[fountain.countStateInts()];
        StateSlab slab = new StateSlab();
        int fireworksSeen = 0;
        int sparksSeen = 0;
        for (int frame = 0; frame < 900; ++frame) {
            // frames of 0, 1, 2 and 3 steps, as the clock gives at a time scale
            for (int s = 0; s < frame % 4; ++s) {
                fountain.step(H);
            }
            if (frame == 300) {
                slab.point(saved, 0, saved.length);
                fountain.writeState(slab);
            }
            if (frame == 500) {
                fountain.reset(); // every slot back in the pool at once
            }
            if (frame == 700) {
                slab.point(saved, 0, saved.length);
                fountain.readState(slab); // the pool as it was at frame 300
            }
            points.update(fountain);
            everySlot(fountain, expectedPositions, expectedColours);
            assertSameBuffers(expectedPositions, expectedColours, mesh, frame);
            fireworksSeen = Math.max(fireworksSeen, fountain.countLive(Fountain.STAR));
            sparksSeen = Math.max(sparksSeen, fountain.countLive(Fountain.SPARK));
        }
        // the run had stars and sparks fading and a pool in full flow
        assertTrue(fireworksSeen > 0, "no stars");
        assertTrue(sparksSeen > 0, "no sparks");
    }

    @Test
    void anUpdateAllocatesNothing() {
        Fountain fountain = new Fountain(POOL);
        // the app's own launch has no Vector API (README), so its fountain steps by the
        // scalar batch, which allocates nothing from the first call; the Vector API's batch
        // (this test JVM has the module) boxes its vectors until C2 has compiled it, which a
        // loaded machine may not do within the warm-up (seen: 15 MB in 30 steps)
        fountain.getIntegrator().batch().setVectorBatch(false);
        PointCloudMesh mesh = new PointCloudMesh(POOL, Fountain.REGION_TOP);
        FountainPoints points = new FountainPoints(mesh, WATER_BRIGHTNESS);
        for (int step = 0; step < 300; ++step) {
            fountain.step(H);
        }
        long bytes = Allocations.warmBytesAllocatedBy(() -> {
            for (int frame = 0; frame < 30; ++frame) {
                fountain.step(H);
                points.update(fountain);
            }
        });
        assertEquals(0L, bytes, "30 steps and mesh updates allocated");
    }

    /**
     * The update before issue 23, into the expected buffers: every slot, one put each, the
     * positions in the planar layout.
     */
    private static void everySlot(Fountain fountain, FloatBuffer[] positions,
            ByteBuffer colours) {
        float[] planar = fountain.getPositions();
        int n = fountain.getCapacity();
        for (int i = 0; i < n; ++i) {
            positions[0].put(i, planar[i]);
            positions[1].put(i, planar[n + i]);
            positions[2].put(i, planar[2 * n + i]);
        }
        for (int i = 0; i < n; ++i) {
            byte kind = fountain.getKind(i);
            float brightness = kind == Fountain.DORMANT ? 0f : kind == Fountain.WATER
                    ? WATER_BRIGHTNESS : kind == Fountain.SHELL ? 1f : fountain.fuseFraction(i);
            int rgb = fountain.getColour(i);
            int at = 4 * i;
            colours.put(at, (byte) Math.round(((rgb >> 16) & 0xff) * brightness));
            colours.put(at + 1, (byte) Math.round(((rgb >> 8) & 0xff) * brightness));
            colours.put(at + 2, (byte) Math.round((rgb & 0xff) * brightness));
            colours.put(at + 3, (byte) 0xff);
        }
    }

    private static void assertSameBuffers(FloatBuffer[] positions, ByteBuffer colours,
            PointCloudMesh mesh, int frame) {
        for (int axis = 0; axis < AXES; ++axis) {
            FloatBuffer actual = mesh.getPositionData(axis);
            assertEquals(POOL, actual.limit(), "one float a point on axis " + axis);
            for (int k = 0; k < POOL; ++k) {
                // bits, not values: the same floats copied, no arithmetic
                if (Float.floatToRawIntBits(positions[axis].get(k))
                        != Float.floatToRawIntBits(actual.get(k))) {
                    throw new AssertionError("frame " + frame + ": point " + k + "'s "
                            + "xyz".charAt(axis) + " is " + actual.get(k) + ", the copy of"
                            + " every slot gives " + positions[axis].get(k));
                }
            }
        }
        ByteBuffer actualColours = mesh.getColourData();
        for (int k = 0; k < 4 * POOL; ++k) {
            if (colours.get(k) != actualColours.get(k)) {
                throw new AssertionError("frame " + frame + ": colour byte " + k + " (point "
                        + k / 4 + ") is " + actualColours.get(k) + ", the copy of every slot"
                        + " gives " + colours.get(k));
            }
        }
    }
}
