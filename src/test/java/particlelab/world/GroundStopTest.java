package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.aiming.Landing;
import particlelab.aiming.ShotSimulator;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * The lecture's "stop at the ground". Built from world parts (a point body, the ground plane,
 * the swept test and the stick response) it lands where {@link ShotSimulator} says: the same
 * crossing of the same straight segment. The world places the body in float ({@code P + f·h·V}
 * with f a float) where the simulator interpolates in double, so they agree to float round-off
 * of the 100 m landing, a few times 1e-5 m. {@link GroundStop} is that rule with its landings:
 * its landing time and point are the float trajectory's linear interpolation, and the state it
 * keeps below the ground is the Euler step's own.
 */
class GroundStopTest {

    private static final float H = 1f / 60f;
    /** The lecture's launch of the reference table: (20, 30) m/s from the ground. */
    private static final float VX = 20f;
    private static final float VY = 30f;
    private static final float G = Gravity.STANDARD_G;

    @Test
    void stickingToTheGroundLandsWhereTheShotSimulatorDoes() {
        // HelloAiming: S = 100 m, vx = 20 m/s, the lecture's vy = g·S/(2·vx) = 24.5 m/s
        // lands vx·h = 0.33 m short when stepped.
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Landing landing = new Landing();
        assertTrue(new ShotSimulator(gravity, 1f, H, 60f).fire(20f, 24.5f, landing));

        World world = new World();
        Body shot = world.addBody(gravity, Vector3f.ZERO, new Vector3f(20f, 24.5f, 0f), 1f, 0f);
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        for (int i = 0; i < 600 && !shot.isHeld(); ++i) {
            world.step(H);
        }
        assertTrue(shot.isHeld());
        assertEquals(landing.getX(), shot.getPosition().x, 5e-5);
        assertEquals(0f, shot.getPosition().y, 1e-5f);
        assertEquals(landing.getTimeSeconds(), shot.getScriptedSinceSeconds(), 1e-6);
        assertEquals(100.0 - 20.0 * H, landing.getX(), 1e-3, "vx·h short");
    }

    @Test
    void landingTimeAndPointAreTheFloatTrajectorysLinearInterpolation() {
        // The trajectory re-simulated in float, in Java's order: V += h·a, then P += h·V.
        float x = 0f;
        float y = 0f;
        float vy = VY;
        float previousX = 0f;
        float previousY = 0f;
        int steps = 0;
        while (!(y < 0f)) {
            previousX = x;
            previousY = y;
            vy = vy + H * -G;
            x = x + H * VX;
            y = y + H * vy;
            ++steps;
        }
        // The plane's swept test on that segment (in double), its fraction kept as a float.
        float fraction = (float) (previousY / ((double) previousY - y));
        // Not the NUMERICS hazard of a crossing on a step: then y < 0 is round-off's choice.
        assertTrue(fraction > 0.01f && fraction < 0.99f, "fraction " + fraction);
        double startSeconds = 0.0;
        for (int i = 1; i < steps; ++i) {
            startSeconds += H;
        }
        double expectedSeconds = startSeconds + (double) fraction * H;
        float expectedX = previousX + fraction * H * VX;

        World world = new World();
        GroundStop stop = new GroundStop(world);
        Body shot = world.addBody(new ParticleIntegrator(new Gravity()), Vector3f.ZERO,
                new Vector3f(VX, VY, 0f), 1f, 0f);
        int index = stop.add(shot);
        int taken = stepUntilHeld(world, shot);

        assertEquals(steps, taken, "the landing step is the first with y < 0");
        assertTrue(stop.hasLanded(index));
        assertTrue(stop.hasLandedThisStep(index));
        // Bit for bit: the same floats, the same double sums.
        assertEquals(expectedSeconds, stop.getLandingSeconds(index), 0.0);
        assertEquals(expectedX, stop.getLandingX(index), 0f);
        assertEquals(0f, shot.getPosition().y, 0f, "on the ground exactly");
        assertEquals(expectedX, shot.getPosition().x, 0f);

        // The closed form of the Euler step (NUMERICS): y_n = n·h·vy − g·h²·n(n+1)/2, the
        // crossing interpolated between y_(N−1) and y_N, all in double. The float trajectory
        // rounds each of its N ≈ 370 additions by at most half an ulp of |y| ≤ 46 m (2e-6 m),
        // so y_N is off by at most 1e-3 m and the crossing by that over the landing speed
        // |vy| ≈ 30 m/s: 4e-5 s. (It comes out near 1e-6 s.)
        double h = H;
        double yBefore = closedFormY(steps - 1, h);
        double yAfter = closedFormY(steps, h);
        double closedFraction = yBefore / (yBefore - yAfter);
        double closedSeconds = (steps - 1 + closedFraction) * h;
        assertEquals(closedSeconds, stop.getLandingSeconds(index), 4e-5);
        // x = vx·t exactly in the closed form; the float x adds vx·h's rounding per step too.
        assertEquals(VX * closedSeconds, stop.getLandingX(index), 20.0 * 4e-5 + 1e-3);
    }

    @Test
    void theStateBelowTheGroundIsTheLandingStepsOwnTakenOnce() {
        // A force that adds nothing and counts the integrator's calls of it.
        int[] calls = new int[1];
        Force counting = new Force() {
            @Override
            public void addForce(Particle particle, Vector3f netForce) {
                ++calls[0];
            }

            @Override
            public String describe() {
                return "nothing, counted";
            }
        };
        ParticleIntegrator forces = new ParticleIntegrator(new Gravity(), counting);
        World world = new World();
        GroundStop stop = new GroundStop(world);
        Body shot = world.addBody(forces, Vector3f.ZERO, new Vector3f(VX, VY, 0f), 1f, 0f);
        int index = stop.add(shot);
        assertEquals(index, stop.add(shot), "adding again changes nothing");
        assertEquals(1, world.countRules());
        assertSame(stop.getRule(), world.getRule(0));

        Particle reference = new Particle(Vector3f.ZERO, new Vector3f(VX, VY, 0f), 1f);
        ParticleIntegrator referenceForces = new ParticleIntegrator(new Gravity());
        int taken = stepUntilHeld(world, shot);
        for (int i = 0; i < taken; ++i) {
            referenceForces.step(reference, H);
        }
        assertEquals(taken, calls[0], "each step integrated once, the landing step too");
        Particle below = stop.getStateBelowGround(index);
        assertTrue(below.position.y < 0f);
        assertEquals(reference.position, below.position, "P of the landing step, bit for bit");
        assertEquals(reference.velocity, below.velocity, "V of the landing step, bit for bit");
        // The stick left the body at rest on the ground: the state below is the stop's copy.
        assertEquals(Vector3f.ZERO, shot.getVelocity());

        // The next step is no landing step; the landing stays.
        world.step(H);
        assertFalse(stop.hasLandedThisStep(index));
        assertTrue(stop.hasLanded(index));
    }

    @Test
    void aRestartForgetsTheLandingAndTheStateRecordPutsItBack() {
        World world = new World();
        GroundStop stop = new GroundStop(world);
        Body shot = world.addBody(new ParticleIntegrator(new Gravity()), Vector3f.ZERO,
                new Vector3f(VX, VY, 0f), 1f, 0f);
        int index = stop.add(shot);
        assertEquals(-1, stop.indexOf(null));
        stepUntilHeld(world, shot);
        float x = stop.getLandingX(index);
        double seconds = stop.getLandingSeconds(index);
        int[] saved = new int[stop.countStateInts()];
        assertEquals(GroundStop.STATE_INTS_PER_BODY, saved.length);
        StateSlab slab = new StateSlab();
        slab.point(saved, 0, saved.length);
        stop.writeState(slab);

        world.restart();
        stop.restart(index);
        assertFalse(stop.hasLanded(index));
        assertTrue(Float.isNaN(stop.getLandingX(index)));
        assertTrue(Double.isNaN(stop.getLandingSeconds(index)));
        assertFalse(shot.isHeld());
        assertEquals(0.0, shot.getFlightSeconds());

        slab.point(saved, 0, saved.length);
        stop.readState(slab);
        assertTrue(stop.hasLanded(index));
        assertEquals(x, stop.getLandingX(index), 0f);
        assertEquals(seconds, stop.getLandingSeconds(index), 0.0);
    }

    /** The Euler step's height after n steps, exactly (NUMERICS), with g and vy as floats. */
    private static double closedFormY(int n, double h) {
        return n * h * VY - (double) G * h * h * n * (n + 1) / 2.0;
    }

    /** Step until the body is held (it landed); return the steps taken. */
    private static int stepUntilHeld(World world, Body body) {
        int steps = 0;
        while (!body.isHeld()) {
            world.step(H);
            ++steps;
            assertTrue(steps < 10_000, "never landed");
        }
        return steps;
    }
}
