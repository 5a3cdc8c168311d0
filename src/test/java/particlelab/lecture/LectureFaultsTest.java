package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;

/**
 * The bug hunt's fault switches ({@code --set fault=...}) in plain JUnit: each fault's motion
 * against a closed form or a re-simulation of the faulty code written here, "spot the fault"
 * (seeded, hidden, revealed), and, with every switch off, the very bits the demos stepped
 * before the switches existed.
 */
class LectureFaultsTest {

    private static final int FRAMES = 600;
    private static final float H = 1f / 60f;
    private static final double G = 9.8;
    /**
     * FNV-1a of every particle's P and V bits after each of 600 frames of 1/60 s, recorded
     * with {@link #runBits} on the demos as they were before the fault switches (commit
     * b7a0f72): with every switch off a run must give these bits.
     */
    private static final long DRAG_BEFORE = 0xa45dc62ac989ae46L;
    private static final long THRUST_BEFORE = 0x8758c7d0bdeee5d6L;
    private static final long PULL_BEFORE = 0x4e81c040b7d3cae6L;
    /** The same for HelloAiming, recorded at fdfab7b, before its y >= 0 loop's switch. */
    private static final long AIMING_BEFORE = 0xa2776bd0e1f710b2L;

    @Test
    void everySwitchOffStepsTheSameBitsAsBefore() {
        assertEquals(DRAG_BEFORE, runBits(new DragDemo()));
        assertEquals(THRUST_BEFORE, runBits(new ThrustDemo()));
        // pull's bug-hunt twin flies hidden with the ball while off: the demo's own particles,
        // the ones there were before it, step the bits they stepped then
        GravitationalPullDemo pull = new GravitationalPullDemo();
        assertEquals(PULL_BEFORE, runBits(pull, later(pull)));
        pull = new GravitationalPullDemo();
        switchFault(pull, GravitationalPullDemo.P_BEFORE_V);
        switchFault(pull, FaultHunt.NONE);
        assertEquals(PULL_BEFORE, runBits(pull, later(pull)));
        assertEquals(AIMING_BEFORE, runBits(new HelloAimingDemo()));
        HelloAimingDemo aiming = new HelloAimingDemo();
        switchFault(aiming, HelloAimingDemo.Y_LOOP);
        switchFault(aiming, FaultHunt.NONE);
        assertEquals(AIMING_BEFORE, runBits(aiming));
        assertFalse(aiming.isSlideInShot(), "fault=none flies the recipe alone again");
        // the fault moves the twin alone: the ball's bits are the same with it on
        pull = new GravitationalPullDemo();
        switchFault(pull, GravitationalPullDemo.P_BEFORE_V);
        assertEquals(PULL_BEFORE, runBits(pull, later(pull)));
        // fault=none set explicitly, after a fault ran: the same bits again
        DragDemo drag = new DragDemo();
        switchFault(drag, DragDemo.SLIDE_DRAG);
        switchFault(drag, FaultHunt.NONE);
        assertEquals(DRAG_BEFORE, runBits(drag));
        ThrustDemo thrust = new ThrustDemo();
        switchFault(thrust, ThrustDemo.UNNORMALISED);
        switchFault(thrust, FaultHunt.NONE);
        assertEquals(THRUST_BEFORE, runBits(thrust));
        // and a fault changes them (the hash sees the switch)
        ThrustDemo faulty = new ThrustDemo();
        switchFault(faulty, ThrustDemo.OTHER_VELOCITY);
        assertFalse(THRUST_BEFORE == runBits(faulty));
    }

    @Test
    void thrustAlongTheOtherSpheresVelocityMatchesTheFaultyCode() {
        ThrustDemo demo = new ThrustDemo();
        switchFault(demo, ThrustDemo.OTHER_VELOCITY);
        assertEquals(ThrustDemo.OTHER_VELOCITY, demo.getActiveFault());
        // The faulty listing in double: the pull + drag sphere steps first (the world's
        // order), then the thruster pushes k along that sphere's new velocity; once the other
        // sphere has stuck at the ground its velocity is 0 and there is no heading to push.
        double b = ThrustDemo.LINEAR_B;
        double k = ThrustDemo.THRUST_K;
        double[] other = {0, 0, 10, 10};
        double[] ship = {0, 0, 10, 10};
        boolean otherFlies = true;
        DemoParticle thruster = demo.getParticles().get(1);
        int steps = 0;
        while (!thruster.hasLanded()) {
            demo.getRun().advancePhysics(H);
            ++steps;
            boolean otherLanded = false;
            if (otherFlies) {
                other[2] += H * (-b * other[2]);
                other[3] += H * (-G - b * other[3]);
                other[0] += H * other[2];
                double y = other[1];
                other[1] += H * other[3];
                otherLanded = y >= 0 && other[1] < 0;
            }
            double speed = Math.hypot(other[2], other[3]);
            double fx = speed > 0 ? k * other[2] / speed : 0;
            double fy = speed > 0 ? k * other[3] / speed : 0;
            ship[2] += H * (-b * ship[2] + fx);
            ship[3] += H * (-G - b * ship[3] + fy);
            ship[0] += H * ship[2];
            ship[1] += H * ship[3];
            if (otherLanded) {
                otherFlies = false;
                other[2] = 0;
                other[3] = 0;
            }
            if (!thruster.hasLanded()) {
                // float32 against double over at most 200 steps of |P| < 30 m: each step
                // rounds by about |P|·2^-24 = 2e-6 m, so 1e-3 m holds the sum with room and is
                // still 1/1000 of the fault's effect below
                Vector3f p = thruster.getParticle().position;
                assertEquals(ship[0], p.x, 1e-3, "x at step " + steps);
                assertEquals(ship[1], p.y, 1e-3, "y at step " + steps);
            }
            assertTrue(steps < 1000, "the thruster should land");
        }
        // The consequence flown ahead is the scene's own landing (the world's swept crossing
        // in float against the flight's in double: 1e-4 m), and the fault moves it by more
        // than 50 times the tolerance the path was checked with (measured: 0.11 m short).
        FaultConsequence consequence = demo.getFaultConsequence();
        assertEquals(consequence.getFaultyLandingX(), thruster.getLandingX(), 1e-4);
        assertTrue(consequence.getCorrectLandingX() - consequence.getFaultyLandingX() > 0.05,
                consequence.getFaultyLandingX() + " vs " + consequence.getCorrectLandingX());
        ThrustDemo correct = new ThrustDemo();
        while (!correct.getParticles().get(1).hasLanded()) {
            correct.getRun().advancePhysics(H);
        }
        assertEquals(correct.getParticles().get(1).getLandingX(),
                consequence.getCorrectLandingX(), 1e-4);
    }

    @Test
    void unnormalisedThrustIsLinearDragWithTheSignTurned() {
        ThrustDemo demo = new ThrustDemo();
        switchFault(demo, ThrustDemo.UNNORMALISED);
        // F = k·V beside −b·V: a = g + r·V with r = (k − b)/m = 1.1 /s. The Euler step's own
        // solution, q = 1 + r·h: V_n = qⁿ·(V0 + g/r) − g/r, and with P_n = P0 + h·ΣV_i,
        // P_n = (V0 + g/r)·q·(qⁿ − 1)/r − n·h·g/r (g = (0, −9.8)).
        double r = (ThrustDemo.THRUST_K - ThrustDemo.LINEAR_B) / 1.0;
        double q = 1.0 + r * H;
        double[] shifted = {10.0, 10.0 - G / r};
        DemoParticle thruster = demo.getParticles().get(1);
        for (int n = 1; n <= 300; ++n) {
            demo.getRun().advancePhysics(H);
            double grown = Math.pow(q, n);
            double x = shifted[0] * q * (grown - 1.0) / r;
            // g/r has y = −9.8/r, so −n·h·g/r adds n·h·9.8/r to y
            double y = shifted[1] * q * (grown - 1.0) / r + n * H * G / r;
            // float32: each step rounds P and V by 2^-24 relative, and the growth carries
            // the errors along, so after n ≤ 300 steps 300·6e-8 = 2e-5 relative; 1e-4 relative
            Vector3f p = thruster.getParticle().position;
            assertEquals(x, p.x, 1e-4 * Math.abs(x) + 1e-6, "x at step " + n);
            assertEquals(y, p.y, 1e-4 * Math.abs(y) + 1e-6, "y at step " + n);
        }
        assertFalse(thruster.hasLanded());
        // Here V0 + g/r points up (10 − 8.9 > 0): it climbs forever, and the HUD says so.
        StringBuilder hud = new StringBuilder();
        demo.writeHudLines(hud);
        assertTrue(hud.toString().contains("never lands"), hud.toString());
        // k·|V0| = 2·√200 = 28.28 N at launch
        assertTrue(hud.toString().contains("pushes k|V| = 28.28 N"), hud.toString());
    }

    @Test
    void slidesDragRunsUnderThePhysicalLabel() {
        DragDemo demo = new DragDemo();
        switchFault(demo, DragDemo.SLIDE_DRAG);
        DemoParticle sphere = demo.getParticles().get(2);
        assertEquals("quadratic drag  F = -c |V|V  [FAULT: slide's |V|²V]", sphere.getLabel());
        // The slide's listing in double: F = −c·|V|²·V, then V and P.
        double c = DragDemo.QUADRATIC_C;
        double[] s = {0, 0, 10, 10};
        int steps = 0;
        while (!sphere.hasLanded()) {
            demo.getRun().advancePhysics(H);
            ++steps;
            double speedSquared = s[2] * s[2] + s[3] * s[3];
            s[2] += H * (-c * speedSquared * s[2]);
            s[3] += H * (-G - c * speedSquared * s[3]);
            s[0] += H * s[2];
            s[1] += H * s[3];
            if (!sphere.hasLanded()) {
                // as for the thrust: float32 against double over < 200 steps, 1e-3 m
                assertEquals(s[0], sphere.getParticle().position.x, 1e-3, "x at " + steps);
                assertEquals(s[1], sphere.getParticle().position.y, 1e-3, "y at " + steps);
            }
            assertTrue(steps < 1000, "the sphere should land");
        }
        FaultConsequence consequence = demo.getFaultConsequence();
        assertEquals(consequence.getFaultyLandingX(), sphere.getLandingX(), 1e-4);
        DragDemo physical = new DragDemo();
        while (!physical.getParticles().get(2).hasLanded()) {
            physical.getRun().advancePhysics(H);
        }
        assertEquals(physical.getParticles().get(2).getLandingX(),
                consequence.getCorrectLandingX(), 1e-4);
        assertTrue(consequence.getCorrectLandingX() - consequence.getFaultyLandingX() > 0.5,
                consequence.getFaultyLandingX() + " vs " + consequence.getCorrectLandingX());
    }

    @Test
    void positionBeforeVelocityLandsAWholeStepLongInsteadOfShort() {
        GravitationalPullDemo demo = new GravitationalPullDemo();
        DemoParticle twin = demo.getFaultTwin();
        // off, the twin flies the lecture's order hidden: the ball's floats, the same landing
        assertTrue(twin.isParked(), "the twin is out of the HUD while the fault is off");
        while (!twin.hasLanded()) {
            demo.getRun().advancePhysics(H);
        }
        assertEquals(demo.getParticles().get(0).getLandingX(), twin.getLandingX(), 0f);
        switchFault(demo, GravitationalPullDemo.P_BEFORE_V);
        assertEquals(GravitationalPullDemo.P_BEFORE_V, demo.getActiveFault());
        assertEquals("twin  [FAULT: P before V]", twin.getLabel());
        DemoParticle ball = demo.getParticles().get(0);
        // The faulty code re-simulated in float32 in Java's order: P += h·V with the old V,
        // then V += h·g (g as the force has it, -9.8f). The twin's every state is these bits.
        float h = H;
        float px = 0f;
        float py = 0f;
        float vx = 10f;
        float vy = 10f;
        float gy = -9.8f;
        int steps = 0;
        while (!twin.hasLanded()) {
            demo.getRun().advancePhysics(h);
            ++steps;
            px = px + h * vx;
            py = py + h * vy;
            vx = vx + h * 0f;
            vy = vy + h * gy;
            if (!twin.hasLanded()) {
                assertEquals(px, twin.getParticle().position.x, 0f, "x at step " + steps);
                assertEquals(py, twin.getParticle().position.y, 0f, "y at step " + steps);
                assertEquals(vy, twin.getParticle().velocity.y, 0f, "vy at step " + steps);
            }
            assertTrue(steps < 1000, "the twin should land");
        }
        while (!ball.hasLanded()) {
            demo.getRun().advancePhysics(h);
        }
        // Closed forms: forward Euler's y_n = n·h·vy0 − g·h²·n(n−1)/2 lies on the parabola
        // launched with vy0 + g·h/2, the lecture's y_n = n·h·vy0 − g·h²·n(n+1)/2 on the one
        // with vy0 − g·h/2: they come down at T ± h, at x = vx·(T ± h), T = 2·vy0/g. The
        // landings are interpolated on the chord between two samples, which lies below the
        // parabola by at most g·h²/8 = 3.4e-4 m; at the ground the path falls |vy| ≈ 10 m/s,
        // so the chord's crossing is within 3.4e-5 s, vx·3.4e-5 = 3.4e-4 m of the parabola's:
        // 1e-3 m holds that and float32's rounding (2e-6 m a step, 125 steps) with room, and
        // is 1/170 of the effect vx·h = 0.167 m.
        double t = 2.0 * 10.0 / G;
        assertEquals(10.0 * (t + H), twin.getLandingX(), 1e-3);
        assertEquals(10.0 * (t - H), ball.getLandingX(), 1e-3);
        assertEquals(2.0 * 10.0 * H, twin.getLandingX() - ball.getLandingX(), 2e-3);
        // the consequence flown ahead is the scene's own (float crossings against double,
        // 1e-4 m)
        assertEquals(twin.getLandingX(), demo.getFaultConsequence().getFaultyLandingX(), 1e-4);
        assertEquals(ball.getLandingX(), demo.getFaultConsequence().getCorrectLandingX(), 1e-4);
        StringBuilder hud = new StringBuilder();
        demo.writeHudLines(hud);
        assertTrue(hud.toString().startsWith("FAULT on: P updated before V (forward Euler)"
                + " (fault=p-before-v): lands at x = 20.57 m, 0.33 m beyond the lecture"
                + " order's 20.24 m (2·Vx·h = 0.33 m)"), hud.toString());
    }

    @Test
    void theYLoopStopsAtTheStepTheListingGives() throws java.io.IOException {
        // vx = 20: S/(vx·h) = 300 is whole. The lecture's vy = g·S/(2·vx) puts the samples
        // y_n = n·h·vy − g·h²·n(n+1)/2 on the ground at n = S/(vx·h) − 1 = 299, so the
        // sample ends ON the crossing, and float rounding decides whether y >= 0 takes one
        // more step (to x = 300·h·vx = S) or stops there: float32 puts sample 299 a hair
        // below 0, so the loop stops at step 299, x = 299·h·20 = 99.67 m, with no overrun.
        assertYLoop(20f, 299, 299 * H * 20.0);
        // vx = 21: S/(vx·h) = 285.71, the parabola meets the ground between samples 284 and
        // 285: the loop stops at the first sample below, step 285, x = 285·h·21 = 99.75 m.
        assertYLoop(21f, 285, 285 * H * 21.0);
        // and the HUD says so in numbers, the crossing interpolated by the recipe's flight
        HelloAimingDemo demo = new HelloAimingDemo();
        switchFault(demo, HelloAimingDemo.Y_LOOP);
        demo.setHorizontalSpeed(21f);
        String line = hudLine(demo);
        assertTrue(line.startsWith("FAULT on: the slide's if (y >= 0) loop (fault=y-loop):"
                + " stops after step 285 at x = 99.75 m, "), line);
        assertTrue(page("docs/demos/aiming.md").contains(line), line);
    }

    /** Fly a shot at vx with the fault on; the slide's bullet stops where the listing does. */
    private static void assertYLoop(float vx, int stopStep, double stopX) {
        HelloAimingDemo demo = new HelloAimingDemo();
        switchFault(demo, HelloAimingDemo.Y_LOOP);
        demo.setHorizontalSpeed(vx);
        assertEquals(HelloAimingDemo.Y_LOOP, demo.getActiveFault());
        assertTrue(demo.isSlideInShot(), "the fault flies the slide's bullet");
        particlelab.aiming.SlideCodeBullet bullet = demo.getSlideBullet();
        float vy = demo.getParticles().get(0).copyLaunchVelocity(new Vector3f()).y;
        // The listing re-simulated in float32 in Java's order: the test first, then
        // V = V + g·tpf, P = P + V·tpf.
        float x = 0f;
        float y = 0f;
        float vyNow = vy;
        int steps = 0;
        while (y >= 0f) {
            vyNow = vyNow + -9.8f * H;
            x = x + vx * H;
            y = y + vyNow * H;
            ++steps;
        }
        assertEquals(stopStep, steps, "the listing's own stop at vx = " + vx);
        for (int frame = 0; frame < 2 * stopStep; ++frame) {
            demo.getRun().advancePhysics(H);
        }
        assertTrue(bullet.isStopped());
        assertEquals(stopStep, bullet.getSteps(), "the slide bullet's steps at vx = " + vx);
        assertEquals(x, bullet.position.x, 0f);
        assertEquals(stopStep, demo.getFaultStopStep());
        // float32 sums of 300 steps of vx·h: each rounds by 2^-24 of x < 100 m, 2e-3 m in all
        // at most; the closed form's x is exact
        assertEquals(stopX, bullet.position.x, 2e-3, "stop x at vx = " + vx);
    }

    @Test
    void spotTheFaultPicksBySeedHidesThenReveals() {
        // SplitMix64's first double seeded with the seed's float bits (as new SplittableRandom(
        // Float.floatToIntBits(s)).nextDouble(), computed with the JDK's): 0.990 for seed 1
        // picks the second of two faults, 0.438 for seed 3 the first.
        assertEquals(1, FaultHunt.pick(1f, 2));
        assertEquals(0, FaultHunt.pick(3f, 2));
        ThrustDemo demo = new ThrustDemo();
        demo.getParameters().set("seed", 3f);
        switchFault(demo, FaultHunt.RANDOM);
        assertEquals(ThrustDemo.OTHER_VELOCITY, demo.getActiveFault());
        DemoParticle thruster = demo.getParticles().get(1);
        assertEquals("pull + drag + thrust k  [FAULT: ?]", thruster.getLabel());
        StringBuilder hud = new StringBuilder();
        demo.writeHudLines(hud);
        String hidden = hud.toString();
        assertTrue(hidden.contains("SPOT THE FAULT (seed 3): one of 2 lecture-code faults is on."
                + " Which? B reveals it"), hidden);
        assertFalse(hidden.contains("other sphere") || hidden.contains("lands"), hidden);
        // the same seed picks the same fault at every reset
        demo.restart();
        assertEquals(ThrustDemo.OTHER_VELOCITY, demo.getActiveFault());
        demo.revealFault();
        assertEquals("pull + drag + thrust k  [FAULT: other sphere's V]", thruster.getLabel());
        hud.setLength(0);
        demo.writeHudLines(hud);
        String shown = hud.toString();
        assertTrue(shown.startsWith("FAULT on: thrust along the other sphere's velocity"
                + " (fault=other-velocity): lands at x = "), shown);
        // the numbers are the flights': the faulty landing and the correct one
        StringBuilder landing = new StringBuilder();
        particlelab.view.TextFormat.appendFixed(landing,
                demo.getFaultConsequence().getFaultyLandingX(), 2);
        assertTrue(shown.contains("x = " + landing + " m"), shown);
        // seed 1 picks the other fault
        demo.getParameters().set("seed", 1f);
        demo.restart();
        assertEquals(ThrustDemo.UNNORMALISED, demo.getActiveFault());
        assertEquals("pull + drag + thrust k  [FAULT: ?]", thruster.getLabel());
    }

    @Test
    void aBadFaultNameIsNotAChoice() {
        ThrustDemo demo = new ThrustDemo();
        int index = demo.getParameters().indexOf(FaultHunt.PARAMETER);
        particlelab.demo.DemoParameter fault = demo.getParameters().get(index);
        assertEquals(-1, fault.indexOfChoice("p-before-v"));
        assertEquals("fault (lecture-code fault) one of none|other-velocity|unnormalised|random",
                fault.appendRange(new StringBuilder()).toString());
    }

    @Test
    void thePagesShowTheHudLinesTheFaultsWrite() throws java.io.IOException {
        // Each page's fault lines are what the HUD writes at the lecture's launch and h.
        String thrustPage = page("docs/demos/thrust.md");
        for (String fault : new String[] {ThrustDemo.OTHER_VELOCITY, ThrustDemo.UNNORMALISED}) {
            ThrustDemo demo = new ThrustDemo();
            switchFault(demo, fault);
            String line = hudLine(demo);
            assertTrue(thrustPage.contains(line), line);
        }
        DragDemo drag = new DragDemo();
        switchFault(drag, DragDemo.SLIDE_DRAG);
        String line = hudLine(drag);
        assertTrue(page("docs/demos/drag.md").contains(line), line);
        GravitationalPullDemo pull = new GravitationalPullDemo();
        switchFault(pull, GravitationalPullDemo.P_BEFORE_V);
        line = hudLine(pull);
        assertTrue(page("docs/demos/pull.md").contains(line), line);
        // the lecture page quotes the hidden line and the revealed consequence
        String lecturing = page("docs/lecturing.md").replace("\n   ", " ");
        ThrustDemo spot = new ThrustDemo();
        spot.getParameters().set("seed", 3f);
        switchFault(spot, FaultHunt.RANDOM);
        String hidden = hudLine(spot);
        assertTrue(lecturing.contains(hidden), hidden);
        spot.revealFault();
        String shown = hudLine(spot);
        String consequence = shown.substring(shown.indexOf("lands at"));
        assertTrue(lecturing.contains(consequence), consequence);
    }

    /** The demo's bug-hunt HUD line (its demo lines start with it), without the newline. */
    private static String hudLine(DemoState demo) {
        StringBuilder text = new StringBuilder();
        if (demo instanceof ThrustDemo) {
            ((ThrustDemo) demo).writeHudLines(text);
        } else if (demo instanceof HelloAimingDemo) {
            ((HelloAimingDemo) demo).writeHudLines(text);
        } else if (demo instanceof GravitationalPullDemo) {
            ((GravitationalPullDemo) demo).writeHudLines(text);
        } else {
            ((DragDemo) demo).writeHudLines(text);
        }
        return text.substring(0, text.indexOf("\n"));
    }

    private static String page(String path) throws java.io.IOException {
        return java.nio.file.Files.readString(java.nio.file.Path.of(path));
    }

    @Test
    void aFlightWithAFaultAllocatesNothing() {
        // Per-frame code allocates nothing: the faulty forces, the HUD line, the consequence
        // flown again at each launch. Each window is a launch and its flight (100 frames, the
        // HUD line every frame); the JIT may still allocate while it compiles, so, as
        // app/FrameAllocationHeadlessTest does, the least of five windows after 30 to warm up.
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean)
                java.lang.management.ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        ThrustDemo demo = new ThrustDemo();
        demo.getParameters().set("seed", 3f);
        switchFault(demo, FaultHunt.RANDOM);
        demo.revealFault();
        assertEquals(0L, leastBytes(threads, thread, demo, demo::writeHudLines));
        // pull's twin, P before V: its velocity half after each step, its flight ahead
        GravitationalPullDemo pull = new GravitationalPullDemo();
        switchFault(pull, FaultHunt.RANDOM);
        pull.revealFault();
        assertEquals(0L, leastBytes(threads, thread, pull, pull::writeHudLines));
        // aiming's y >= 0 loop: its HUD line, with the flight ahead flown again for each new
        // vx (the listing's own bullet allocates by design, so only the HUD is measured)
        HelloAimingDemo aiming = new HelloAimingDemo();
        switchFault(aiming, HelloAimingDemo.Y_LOOP);
        StringBuilder hud = new StringBuilder(4096);
        long least = Long.MAX_VALUE;
        for (int window = 0; window < 35; ++window) {
            aiming.setHorizontalSpeed(window % 2 == 0 ? 21f : 20f);
            long before = threads.getThreadAllocatedBytes(thread);
            for (int frame = 0; frame < 100; ++frame) {
                hud.setLength(0);
                aiming.writeHudLines(hud);
            }
            long bytes = threads.getThreadAllocatedBytes(thread) - before;
            if (window >= 30) {
                least = Math.min(least, bytes);
            }
        }
        assertEquals(0L, least);
    }

    /** The least bytes of five launch-and-flight windows after 30 to warm up. */
    private static long leastBytes(com.sun.management.ThreadMXBean threads, long thread,
            DemoState demo, java.util.function.Consumer<StringBuilder> hudLines) {
        StringBuilder hud = new StringBuilder(4096);
        long least = Long.MAX_VALUE;
        for (int window = 0; window < 35; ++window) {
            long before = threads.getThreadAllocatedBytes(thread);
            demo.restart();
            for (int frame = 0; frame < 100; ++frame) {
                demo.getRun().advancePhysics(H);
                hud.setLength(0);
                hudLines.accept(hud);
            }
            long bytes = threads.getThreadAllocatedBytes(thread) - before;
            if (window >= 30) {
                least = Math.min(least, bytes);
            }
        }
        return least;
    }

    /** Set the fault switch by name and launch again (it applies at the next launch). */
    private static void switchFault(DemoState demo, String name) {
        int index = demo.getParameters().indexOf(FaultHunt.PARAMETER);
        int choice = demo.getParameters().get(index).indexOfChoice(name);
        assertTrue(choice >= 0, name);
        demo.getParameters().set(FaultHunt.PARAMETER, choice);
        demo.restart();
    }

    /** Hash every particle's P and V bits after each of 600 frames of 1/60 s (FNV-1a). */
    static long runBits(DemoState demo) {
        return runBits(demo, (DemoParticle) null);
    }

    /** The same, leaving out one particle (a bug hunt's twin, which came after the hashes). */
    static long runBits(DemoState demo, DemoParticle leftOut) {
        return runBits(demo, particle -> particle == leftOut);
    }

    /**
     * The particles pull gained after the hashes: the bug hunt's twin.
     */
    private static java.util.function.Predicate<DemoParticle> later(
            GravitationalPullDemo pull) {
        return particle -> particle == pull.getFaultTwin();
    }

    /** The same, leaving out the particles that came after the hashes. */
    static long runBits(DemoState demo, java.util.function.Predicate<DemoParticle> leftOut) {
        long hash = 0xcbf29ce484222325L;
        for (int frame = 0; frame < FRAMES; ++frame) {
            demo.getRun().advancePhysics(H);
            List<DemoParticle> particles = demo.getParticles();
            for (int i = 0; i < particles.size(); ++i) {
                if (leftOut.test(particles.get(i))) {
                    continue;
                }
                hash = mix(hash, particles.get(i).getParticle().position);
                hash = mix(hash, particles.get(i).getParticle().velocity);
            }
        }
        return hash;
    }

    private static long mix(long hash, Vector3f v) {
        long result = mix(hash, Float.floatToRawIntBits(v.x));
        result = mix(result, Float.floatToRawIntBits(v.y));
        return mix(result, Float.floatToRawIntBits(v.z));
    }

    /** Feed an int's four bytes, lowest first, to FNV-1a 64. */
    private static long mix(long hash, int value) {
        long result = hash;
        for (int b = 0; b < Integer.BYTES; ++b) {
            result ^= (value >>> (Byte.SIZE * b)) & 0xff;
            result *= 0x100000001b3L;
        }
        return result;
    }
}
