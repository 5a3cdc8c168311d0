package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.Allocations;

/**
 * The fountain's pool: bounded, recycled, normal floats only, allocation-free and
 * reproducible.
 */
class FountainTest {

    /**
     * {@link #particleDigestOfARun} of 5000 and 20000 particles, pinned anew when issue 30 made
     * the batch run the recipe's update with the folded a ({@code V + h·(g − σ·V)} instead of
     * {@code V·(1 − h·σ) + h·g}: other roundings, so other bits; under 86d81bd they were
     * -5260714098729664306 and 4176117114969777009).
     */
    private static final long PARTICLES_5000 = 1781168038968483420L;
    private static final long PARTICLES_20000 = 3091532920795974243L;

    private static final float H = 1f / 60f;
    private static final int POOL = 10_000;

    @Test
    void theCountStaysBoundedAndEverySlotIsEitherInFlightOrInThePool() {
        Fountain fountain = new Fountain(POOL);
        int most = 0;
        // 60 s: many lifetimes of water (about 4.5 s) and fifty shells
        for (int step = 0; step < 3600; ++step) {
            fountain.step(H);
            int live = fountain.countLive();
            assertTrue(live >= 0 && live <= POOL, "in flight: " + live);
            most = Math.max(most, live);
            if (step % 100 == 0) {
                assertConsistent(fountain);
            }
        }
        assertConsistent(fountain);
        // water may take all but the fireworks' twentieth; at steady state it nearly does
        assertTrue(most > POOL / 2, "the fountain fills its pool: at most " + most);
        assertTrue(most <= POOL, "at most " + most);
    }

    @Test
    void particlesAtRestOrOutOfTheRegionAreRecycled() {
        Fountain fountain = new Fountain(POOL);
        for (int step = 0; step < 3600; ++step) {
            fountain.step(H);
        }
        long recycled = fountain.countRecycledResting() + fountain.countRecycledLeaving()
                + fountain.countRecycledBurnt();
        // 60 s of water at a fifth of the pool per second: each slot used many times over
        assertTrue(recycled > 5L * POOL, "recycled " + recycled);
        assertTrue(fountain.countRecycledResting() > POOL, "at rest");
        assertTrue(fountain.countRecycledLeaving() > 0, "left the region");
        // a shell every 1.2 s: 50 shells, each bursting once, and their stars too
        assertTrue(fountain.countBursts() > 50 * 100, "bursts " + fountain.countBursts());
        // at rest means: no water is left on the ground that no longer bounces (its rebound,
        // vy after the ground's rule, slower than the rest speed)
        float[] positions = fountain.getPositions();
        float[] velocities = fountain.getVelocities();
        for (int i = 0; i < POOL; ++i) {
            if (fountain.getKind(i) == Fountain.WATER
                    && positions[POOL + i] <= Fountain.RADIUS_METRES) {
                assertTrue(velocities[POOL + i] >= Fountain.REST_SPEED, "water " + i
                        + " lies on the ground rebounding at " + velocities[POOL + i]
                        + " m/s and was not recycled");
            }
        }
    }

    @ParameterizedTest(name = "e = {0}")
    @ValueSource(floats = {0.5f, 1f})
    void noPositionOrVelocityEverBecomesSubnormal(float restitution) {
        // e = 1: the drops bounce for ever and only the age limit recycles them
        Fountain fountain = new Fountain(POOL);
        fountain.getGround().setRestitution(restitution);
        float[] positions = fountain.getPositions();
        float[] velocities = fountain.getVelocities();
        // 2 minutes: 6 times the age limit, long enough for a drag-only decay
        // (v·(1 − h·b/m)^n) to have reached subnormals at k = 0.5 (NUMERICS: ~10^4 steps)
        for (int step = 1; step <= 7200; ++step) {
            fountain.step(H);
            if (step % 60 == 0) {
                assertNormalOrZero(positions, "P", step);
                assertNormalOrZero(velocities, "V", step);
            }
        }
    }

    @Test
    void aRunningStepAllocatesNothing() {
        Fountain fountain = new Fountain(POOL);
        for (int step = 0; step < 600; ++step) {
            fountain.step(H); // past the fill-up, with bursts under way
        }
        Allocations.assertAllocatesNothing("60 fountain steps", () -> {
            for (int step = 0; step < 60; ++step) {
                fountain.step(H);
            }
        });
    }

    @Test
    void aResetReplaysTheSameFountain() {
        Fountain fountain = new Fountain(2_000);
        for (int step = 0; step < 300; ++step) {
            fountain.step(H);
        }
        float[] first = fountain.getPositions().clone();
        fountain.reset();
        assertEquals(0, fountain.countLive());
        for (int step = 0; step < 300; ++step) {
            fountain.step(H);
        }
        assertArrayEquals(first, fountain.getPositions());
    }

    /**
     * The particles in flight, as a set (each one's P, V, kind, colour and fuse, whichever
     * slot holds it), and the counts, every second of 30 s, digest to what the code before
     * the fireworks were kept first in the pool gave (86d81bd, its list of firework slots;
     * that code gave, slot for slot, the bits of e6cee32, before issue 23's second part, as
     * a slot-ordered digest tested until then): the new layout moves particles between
     * slots, not one bit of any particle, and the bursts draw their random numbers in the
     * same order. Water, bounces, bursts and recycling all take part. (Issue 30 changed the
     * step's roundings on purpose; the digests were pinned anew from that code.)
     */
    @Test
    void theStepGivesTheSameParticlesAsBeforeInWhicheverSlots() {
        assertEquals(PARTICLES_5000, particleDigestOfARun(5_000));
        assertEquals(PARTICLES_20000, particleDigestOfARun(20_000));
    }

    /**
     * The fireworks' pass finds, among the fireworks, one too old, one beyond the region's
     * width, one beyond its depth and one above its top (put into a state read back), and
     * sends exactly those four back unburst: four more leaving than the same step of the
     * untouched state. (In a plain run fireworks burn out long before they could age or
     * leave, so the run's digest does not cover these.)
     */
    @Test
    void fireworksTooOldOrOutOfTheRegionGoBackUnburst() {
        Fountain fountain = new Fountain(5_000);
        for (int step = 0; fountain.countFireworks() < 8; ++step) {
            assertTrue(step < 3_000, "no fireworks in flight");
            fountain.step(H);
        }
        int n = fountain.getCapacity();
        int[] state = new int[fountain.countStateInts()];
        StateSlab slab = new StateSlab();
        slab.point(state, 0, state.length);
        fountain.writeState(slab);
        int[] moved = state.clone();
        // the layout of writeState: P (3n floats, x then y then z), V (3n), kinds (n), births
        moved[7 * n] = Float.floatToRawIntBits(-1_000f);
        moved[1] = Float.floatToRawIntBits(Fountain.REGION_HALF_WIDTH + 50f);
        moved[2 * n + 2] = Float.floatToRawIntBits(-Fountain.REGION_HALF_DEPTH - 50f);
        moved[n + 3] = Float.floatToRawIntBits(Fountain.REGION_TOP + 500f);

        slab.point(state, 0, state.length);
        fountain.readState(slab);
        fountain.step(H);
        long leaving = fountain.countRecycledLeaving();
        long bursts = fountain.countBursts();
        slab.point(moved, 0, moved.length);
        fountain.readState(slab);
        fountain.step(H);
        assertEquals(leaving + 4, fountain.countRecycledLeaving());
        assertTrue(fountain.countBursts() <= bursts, "the four went back unburst");
    }

    @Test
    void aCountOutsideOneToAMillionIsRefused() {
        for (int bad : new int[] {0, -5, Fountain.MAX_PARTICLES + 1}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new Fountain(bad));
            assertTrue(e.getMessage().contains("must be from 1 to 1000000, but was " + bad),
                    e.getMessage());
        }
    }

    private static long particleDigestOfARun(int pool) {
        Fountain fountain = new Fountain(pool);
        long hash = 1125899906842597L;
        for (int step = 0; step < 1800; ++step) {
            fountain.step(H);
            if (step % 60 == 0) {
                hash = 31 * hash + particleDigest(fountain);
            }
        }
        return 31 * hash + particleDigest(fountain);
    }

    /** A digest of the particles in flight that does not depend on their order. */
    private static long particleDigest(Fountain fountain) {
        int n = fountain.getCapacity();
        float[] positions = fountain.getPositions();
        float[] velocities = fountain.getVelocities();
        long sum = 0L;
        long xor = 0L;
        for (int i = 0; i < n; ++i) {
            if (fountain.getKind(i) == Fountain.DORMANT) {
                continue;
            }
            long one = fountain.getKind(i);
            one = 31 * one + fountain.getColour(i);
            one = 31 * one + Float.floatToRawIntBits(fountain.fuseFraction(i));
            for (int axis = 0; axis < 3; ++axis) {
                one = 31 * one + Float.floatToRawIntBits(positions[axis * n + i]);
                one = 31 * one + Float.floatToRawIntBits(velocities[axis * n + i]);
            }
            long mixed = mix(one);
            sum += mixed;
            xor ^= mix(mixed);
        }
        long hash = 31 * sum + xor;
        hash = 31 * hash + fountain.countLive();
        for (byte kind = Fountain.WATER; kind <= Fountain.SPARK; ++kind) {
            hash = 31 * hash + fountain.countLive(kind);
        }
        hash = 31 * hash + fountain.countRecycledResting();
        hash = 31 * hash + fountain.countRecycledLeaving();
        hash = 31 * hash + fountain.countRecycledBurnt();
        return 31 * hash + fountain.countBursts();
    }

    /** SplitMix64's finaliser: every bit of the input moves every bit of the output. */
    private static long mix(long value) {
        long z = value + 0x9e3779b97f4a7c15L;
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    private static void assertConsistent(Fountain fountain) {
        int[] byKind = new int[Fountain.SPARK + 1];
        for (int i = 0; i < fountain.getCapacity(); ++i) {
            byKind[fountain.getKind(i)]++;
        }
        assertEquals(fountain.getCapacity() - fountain.countLive(), byKind[Fountain.DORMANT],
                "dormant slots");
        for (byte kind = Fountain.WATER; kind <= Fountain.SPARK; ++kind) {
            assertEquals(byKind[kind], fountain.countLive(kind), "kind " + kind);
        }
        // the particles in flight first, the fireworks first of them: every pass touches
        // only slots 0 .. live - 1, the fireworks' pass only 0 .. fireworks - 1
        int fireworks = fountain.countFireworks();
        assertEquals(byKind[Fountain.SHELL] + byKind[Fountain.STAR] + byKind[Fountain.SPARK],
                fireworks, "fireworks");
        for (int i = 0; i < fountain.getCapacity(); ++i) {
            byte kind = fountain.getKind(i);
            byte expected = i < fireworks ? kind : i < fountain.countLive() ? Fountain.WATER
                    : Fountain.DORMANT;
            assertEquals(expected, kind, "slot " + i + " of " + fireworks + " fireworks and "
                    + fountain.countLive() + " in flight");
            assertTrue(i >= fireworks || kind >= Fountain.SHELL, "slot " + i + " is a firework");
        }
    }

    private static void assertNormalOrZero(float[] values, String what, int step) {
        for (int i = 0; i < values.length; ++i) {
            float v = values[i];
            if (v != 0f && !(Math.abs(v) >= Float.MIN_NORMAL)) {
                throw new AssertionError(what + "[" + i + "] = " + v + " is subnormal (or"
                        + " not finite) after step " + step);
            }
        }
    }
}
