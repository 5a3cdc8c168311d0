package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import particlelab.lecture.DragDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.ThrustDemo;
import particlelab.lecture.UniformMotionDemo;
import particlelab.physics.DerivativeLens;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;
import particlelab.reference.ExactPath;
import particlelab.view.TextFormat;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;

/**
 * The derivative lens on the free-flight demos' HUD ({@link LensPart}), in plain JUnit: its
 * four lines give the values {@link DerivativeLens} computes for the shown step (the live
 * end's, and a replayed one's after steps back), the chord is {@code V_{i+1}}, and the exact
 * tangents are the closed form's under gravity; a click on a step dot shows that step and
 * the lens looks there; the graph's slope of V_y at the chosen step is −g to float rounding
 * under gravity alone and the step's own acceleration under linear drag.
 */
class LensPartTest {

    private static final float H = 1f / 60f;
    /** The lines' decimals, as the part writes them. */
    private static final int DECIMALS = 3;

    /** Switch the lens on as {@code --set lens=on} does. */
    private static <D extends DemoState> D withLens(D demo) {
        demo.getParameters().set(LensPart.PARAMETER, 1f);
        return demo;
    }

    private static void advance(DemoState demo, int steps) {
        demo.getClock().setMode(SimulationClock.Mode.RAW_TPF);
        for (int i = 0; i < steps; ++i) {
            // raw tpf: one frame is one step of H
            demo.getRun().advancePhysics(H);
        }
    }

    /** The HUD line of the arrow of a colour, or fail. */
    private static String line(String hud, String color) {
        String start = "  " + color + ": ";
        for (String line : hud.split("\n")) {
            if (line.startsWith(start)) {
                return line;
            }
        }
        throw new AssertionError("no lens line for " + color + " in\n" + hud);
    }

    /** The value a line shows, as the part formats it. */
    private static String shown(Vector3f value) {
        StringBuilder text = new StringBuilder("(");
        TextFormat.appendFixed(text, value.x, DECIMALS).append(", ");
        return TextFormat.appendFixed(text, value.y, DECIMALS).append(')').toString();
    }

    /** The two numbers at a line's end. */
    private static float[] parse(String line) {
        String pair = line.substring(line.lastIndexOf('(') + 1, line.lastIndexOf(')'));
        String[] parts = pair.split(", ");
        return new float[] {Float.parseFloat(parts[0]), Float.parseFloat(parts[1])};
    }

    /**
     * Assert the HUD's four lens lines show what a {@link DerivativeLens} computes from a
     * state with the sphere's integrator, and the exact path's tangents.
     *
     * @return the lens looked with
     */
    private static DerivativeLens assertLinesFor(String hud, DemoParticle sphere,
            Vector3f position, Vector3f velocity) {
        DerivativeLens lens = new DerivativeLens();
        Particle particle = sphere.getParticle();
        lens.look(sphere.getIntegrator(), particle.getMass(), position, velocity, H);
        ExactPath exact = new ExactPath(sphere.getPathIntegrator());
        exact.start(position, velocity, particle.getMass(), false);
        exact.advance(0.5 * H);
        lens.setExactTangents(velocity, new Vector3f((float) exact.getVelocity(0),
                (float) exact.getVelocity(1), (float) exact.getVelocity(2)));
        assertEquals("  yellow: chord (P_i+1 - P_i)/h = " + shown(lens.chord),
                line(hud, "yellow"));
        assertEquals("  white: V_i+1, the step's velocity = " + shown(lens.stepVelocity),
                line(hud, "white"));
        assertEquals("  orange: exact dP/dt at t_i = " + shown(lens.exactAtStart),
                line(hud, "orange"));
        assertEquals("  green: exact dP/dt at t_i + h/2 = " + shown(lens.exactAtMiddle),
                line(hud, "green"));
        return lens;
    }

    @Test
    void eachFreeFlightDemosLensShowsTheLensValuesOfTheLiveStep() {
        // the followed sphere: the demo's comparison lane follows the same one
        Object[][] cases = {
            {(Supplier<DemoState>) UniformMotionDemo::new, 0},
            {(Supplier<DemoState>) GravitationalPullDemo::new, 0},
            {(Supplier<DemoState>) DragDemo::new, 1},
            {(Supplier<DemoState>) ThrustDemo::new, 1}};
        for (Object[] entry : cases) {
            @SuppressWarnings("unchecked")
            DemoState demo = withLens(((Supplier<DemoState>) entry[0]).get());
            advance(demo, 20);
            DemoParticle sphere = demo.getParticles().get((Integer) entry[1]);
            String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
            assertTrue(hud.contains("derivative lens (O; click a step dot) at step "
                    + demo.getRun().getShownStep() + ", t_i = 0.333 s, h = 0.0167 s"),
                    demo.getTitle() + ":\n" + hud);
            Particle particle = sphere.getParticle();
            DerivativeLens lens = assertLinesFor(hud, sphere, particle.position,
                    particle.velocity);
            // the arrows start at the sphere
            assertEquals(particle.position, lens.startPosition, demo.getTitle());
        }
    }

    @Test
    void underGravityTheChordIsVNextAndTheTangentsAreGhAndHalfGhAway() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        advance(demo, 30);
        DemoParticle ball = demo.getParticles().get(0);
        Vector3f v = ball.getParticle().velocity.clone();
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        float[] chord = parse(line(hud, "yellow"));
        float[] step = parse(line(hud, "white"));
        float[] atStart = parse(line(hud, "orange"));
        float[] atMiddle = parse(line(hud, "green"));
        // the lecture's step: the chord is V_{i+1}, the same text from the same bits
        assertEquals(line(hud, "yellow").substring(line(hud, "yellow").lastIndexOf('(')),
                line(hud, "white").substring(line(hud, "white").lastIndexOf('(')));
        // closed form: V_{i+1} = V_i − g·h, dP/dt(t_i) = V_i, dP/dt(t_i + h/2) = V_i − g·h/2.
        // The lines round to 0.001 m/s: within half of that, plus float's 1e-6 on 10 m/s.
        float g = Gravity.STANDARD_G;
        float tolerance = 0.0005f + 1e-5f;
        assertEquals(v.x, chord[0], tolerance);
        assertEquals(v.y - g * H, chord[1], tolerance);
        assertEquals(v.y - g * H, step[1], tolerance);
        assertEquals(v.y, atStart[1], tolerance);
        assertEquals(v.y - g * H / 2f, atMiddle[1], tolerance);
        // the differences the slide asks about: g·h = 0.163 and g·h/2 = 0.082 m/s
        assertEquals(g * H, atStart[1] - chord[1], 2f * tolerance);
        assertEquals(g * H / 2f, atMiddle[1] - chord[1], 2f * tolerance);
    }

    @Test
    void replayedStepsLensLooksAtTheShownEntrysStep() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        DemoParticle ball = demo.getParticles().get(0);
        int steps = 30;
        Vector3f[] positions = new Vector3f[steps + 1];
        Vector3f[] velocities = new Vector3f[steps + 1];
        advance(demo, 0);
        for (int n = 1; n <= steps; ++n) {
            advance(demo, 1);
            positions[n] = ball.getParticle().position.clone();
            velocities[n] = ball.getParticle().velocity.clone();
        }
        long live = demo.getRun().getShownStep();
        for (int back = 0; back < 3; ++back) {
            assertTrue(demo.getReplayControls().stepBack(), "the ring holds the earlier steps");
        }
        assertTrue(demo.getRun().isReplaying());
        assertEquals(live - 3, demo.getRun().getShownStep());
        int k = steps - 3;
        // the ring gave back step k's state bit for bit
        assertEquals(positions[k], ball.getParticle().position);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("derivative lens (O; click a step dot) at step " + (live - 3)
                + ", t_i = "), hud);
        DerivativeLens lens = assertLinesFor(hud, ball, positions[k], velocities[k]);
        // the step the lens takes again is the one the world took from there, bit for bit
        assertEquals(positions[k + 1], lens.endPosition);
        assertEquals(velocities[k + 1], lens.stepVelocity);
    }

    /**
     * The HUD lines docs/energy.md quotes (the pull demo at its default launch, step 60)
     * are what the lens writes there.
     */
    @Test
    void theEnergyPagesLensLinesAreThePullDemosAtStep60() throws IOException {
        String page = Files.readString(Paths.get("docs", "energy.md"));
        int start = page.indexOf("derivative lens (O; click a step dot) at step 60,");
        assertTrue(start >= 0, "docs/energy.md quotes the lens at step 60");
        String quoted = page.substring(start, page.indexOf("```", start));
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        advance(demo, 60);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains(quoted), "the page quotes\n" + quoted + "the HUD has\n" + hud);
    }

    @Test
    void keyOSwitchesTheLensAndOffItWritesNothing() {
        UniformMotionDemo demo = new UniformMotionDemo();
        advance(demo, 5);
        assertFalse(demo.getWindow().formatHud(new StringBuilder()).toString()
                .contains("derivative lens"));
        KeyBinding lensKey = null;
        for (KeyBinding binding : demo.getKeys().getBindings()) {
            if (binding.getKeyLabel().equals("O")) {
                lensKey = binding;
            }
        }
        assertNotNull(lensKey, "the lens has a key");
        lensKey.press(0);
        assertTrue(demo.getWindow().formatHud(new StringBuilder()).toString()
                .contains("derivative lens"));
        lensKey.press(0);
        assertFalse(demo.getWindow().formatHud(new StringBuilder()).toString()
                .contains("derivative lens"));
    }

    /** A camera facing the plane z = 0 from 30 m, centred on pull's flight (29 px/m). */
    private static Camera faceOnCamera() {
        Camera camera = new Camera(1280, 720);
        camera.setFrustumPerspective(45f, 1280f / 720f, 1f, 1000f);
        camera.setLocation(new Vector3f(10f, 3f, 30f));
        camera.lookAt(new Vector3f(10f, 3f, 0f), Vector3f.UNIT_Y);
        return camera;
    }

    /** The position of a particle in a ring entry, as the run writes it (t, then P, V). */
    private static Vector3f positionAt(StateRing ring, long entry, int particle) {
        StateSlab slab = ring.read(entry);
        slab.getDouble();
        for (int skip = 0; skip < 6 * particle; ++skip) {
            slab.getFloat();
        }
        return new Vector3f(slab.getFloat(), slab.getFloat(), slab.getFloat());
    }

    @Test
    void aClickOnAStepDotShowsThatStepAndTheLensLooksThere() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        advance(demo, 60);
        LensPart part = demo.getLens();
        Camera camera = faceOnCamera();
        long chosen = demo.getRun().getStateRing().getFirstIndex() + 20;
        Vector3f dot = positionAt(demo.getRun().getStateRing(), chosen, 0);
        Vector3f screen = camera.getScreenCoordinates(dot);
        // a press a pixel off the dot: the dots are 6 to 11 px apart here (|V|·h from 0.17
        // to 0.24 m at 29 px/m), so the nearest is still step 20's
        assertTrue(part.clickStepDot(camera, screen.x + 1f, screen.y));
        assertTrue(demo.getRun().isReplaying(), "the click shows a recorded step");
        assertTrue(demo.getClock().isPaused());
        assertEquals(chosen, demo.getRun().getShownStep());
        // the sphere is at that dot, bit for bit, and the lens looks at the step from there
        assertEquals(dot, demo.getParticles().get(0).getParticle().position);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("derivative lens (O; click a step dot) at step " + chosen
                + ", t_i = 0.333 s"), hud);
        assertEquals(dot, part.getLens().startPosition);
        // the steps plotted end at the chosen one and the step looked at
        assertTrue(part.readSteps());
        LensSteps steps = part.getSteps();
        assertEquals(chosen, steps.getEntry(steps.getChosen()));
        assertEquals(steps.getChosen() + 2, steps.size());
    }

    @Test
    void aClickAwayFromTheDotsOrWithTheLensOffChoosesNothing() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        advance(demo, 60);
        Camera camera = faceOnCamera();
        long live = demo.getRun().getShownStep();
        // 10 m above the flight's apex (5.1 m): 290 px from any dot
        Vector3f sky = camera.getScreenCoordinates(new Vector3f(10f, 15f, 0f));
        assertFalse(demo.getLens().clickStepDot(camera, sky.x, sky.y));
        Vector3f dot = camera.getScreenCoordinates(positionAt(demo.getRun().getStateRing(), 20, 0));
        demo.getParameters().set(LensPart.PARAMETER, 0f);
        assertFalse(demo.getLens().clickStepDot(camera, dot.x, dot.y));
        assertFalse(demo.getRun().isReplaying());
        assertEquals(live, demo.getRun().getShownStep());
    }

    @Test
    void onceTheSphereLandedAClickOnADotOfItsFlightLooksThereAgain() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        // the launch at (10, 10) m/s lands after 2.04 s: 150 steps are past it
        advance(demo, 150);
        String landed = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(landed.contains("derivative lens (O): the sphere is not flying;"
                + " click a step dot of its flight\n"), landed);
        Camera camera = faceOnCamera();
        Vector3f dot = positionAt(demo.getRun().getStateRing(), 60, 0);
        Vector3f screen = camera.getScreenCoordinates(dot);
        assertTrue(demo.getLens().clickStepDot(camera, screen.x, screen.y));
        assertEquals(60, demo.getRun().getShownStep());
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("derivative lens (O; click a step dot) at step 60,"), hud);
    }

    @Test
    void theGraphsSlopeOfVyIsMinusGToFloatRoundingUnderGravityAlone() {
        GravitationalPullDemo demo = withLens(new GravitationalPullDemo());
        advance(demo, 90);
        LensPart part = demo.getLens();
        float g = Gravity.STANDARD_G;
        for (int back = 0; back <= 40; back += 20) {
            for (int i = 0; i < 20 && back > 0; ++i) {
                demo.getReplayControls().stepBack();
            }
            assertTrue(part.readSteps());
            LensSteps steps = part.getSteps();
            int chosen = steps.getChosen();
            float vy = steps.getVelocityY()[chosen];
            // V_y,i+1 = V_y,i + fl(h·(−g)) rounded once to float: the difference the graph
            // divides by h is h·g off by at most half an ulp of V_y, so the slope is −g
            // within ulp(V_y)/(2h) (6e-5 m/s² at |V_y| < 8 m/s), plus fl(h·g)'s 6e-8 relative
            double tolerance = Math.ulp(Math.abs(vy)) / (2.0 * H) + 1e-7 * g;
            assertEquals(-g, steps.slopeY(), tolerance, "at step " + demo.getRun().getShownStep());
            // no force along x: V_x is the same float, the slope exactly 0
            assertEquals(0.0, steps.slopeX());
            // the two plotted points are the chosen step and the one the lens looks at
            assertEquals(part.getLens().stepVelocity.y, steps.getVelocityY()[chosen + 1]);
            assertEquals(part.getLens().startVelocity.y, vy);
        }
    }

    @Test
    void underLinearDragTheGraphsSlopeIsTheStepsAccelerationAtTheChosenStep() {
        DragDemo demo = withLens(new DragDemo());
        // early in the flight, V_y still large: the drag's k·V_y is far from 0
        advance(demo, 10);
        demo.getReplayControls().stepBack();
        demo.getReplayControls().stepBack();
        LensPart part = demo.getLens();
        assertTrue(part.readSteps());
        LensSteps steps = part.getSteps();
        int chosen = steps.getChosen();
        double vx = steps.getVelocityX()[chosen];
        double vy = steps.getVelocityY()[chosen];
        // linear drag: a = g − (b/m)·V, and b/m = g/v_t with the demo's terminal speed m·g/b
        double g = Gravity.STANDARD_G;
        double k = g / demo.terminalSpeed(1);
        // the step adds fl(h·a) to V and rounds once: off by half an ulp of |V| over h, and
        // a's float evaluation by a few ulps of its terms (1e-6 relative of g + k·|V|)
        double tolerance = Math.ulp((float) Math.hypot(vx, vy)) / (2.0 * H)
                + 1e-6 * (g + k * Math.hypot(vx, vy));
        assertEquals(-g - k * vy, steps.slopeY(), tolerance);
        assertEquals(-k * vx, steps.slopeX(), tolerance);
        // and the drag shows: the slope is not −g
        assertTrue(Math.abs(steps.slopeY() + g) > 1.0, "slope " + steps.slopeY());
    }
}
