package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link SimulationClock}: frame times in, steps out.
 *
 * <p>Time accounting is kept in double from float inputs, so sums of a few hundred frames are
 * exact to about 1e-16 relative; {@link #ACCOUNTING_TOLERANCE} (1e-12 s) is that with a wide
 * margin, and far below any step (1/60 s) or the 1e-4·h a step may be taken early.
 */
class SimulationClockTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    private static final double ACCOUNTING_TOLERANCE = 1e-12;
    /** How far below zero the leftover may go: the documented 1e-4 of a step. */
    private static final double LEFTOVER_FLOOR = -1e-4 * H;

    @ParameterizedTest
    @ValueSource(floats = {0.25f, 1f, 5f})
    void fixedStepModeSurvivesAHitchWithBoundedStepsAndExactTimeAccounting(float hitch) {
        SimulationClock clock = new SimulationClock();
        // Stiff enough (k = 5/s) that a raw 0.5 s step would already flip and grow V.
        RecordingStepper stepper = RecordingStepper.withParticle(
                new ParticleIntegrator(new Gravity(), new LinearDrag(5f)));
        double fed = 0.0;
        for (int i = 0; i < 30; ++i) {
            fed += feed(clock, H, stepper);
        }
        double simulatedBefore = clock.getSimulatedSeconds();
        double leftoverBefore = clock.getLeftoverSeconds();
        double droppedBefore = clock.getDroppedSeconds();

        int steps = clock.advance(hitch, stepper);
        fed += hitch;

        assertTrue(steps <= clock.getMaxStepsPerFrame(), steps + " steps");
        // 0.25 s is 15 steps of 1/60 s (up to the round-off the clock tolerates).
        assertEquals(15, steps);
        assertTrue(stepper.particle.isFinite(), stepper.particle.toString());
        // What the frame gave the simulation: exactly the clamped frame, no more.
        double accepted = clock.getSimulatedSeconds() - simulatedBefore
                + clock.getLeftoverSeconds() - leftoverBefore;
        assertEquals(SimulationClock.DEFAULT_MAX_FRAME_SECONDS, accepted, ACCOUNTING_TOLERANCE);
        // And the rest, exactly: the difference of two floats is exact in double.
        assertEquals(hitch - (double) SimulationClock.DEFAULT_MAX_FRAME_SECONDS,
                clock.getDroppedSeconds() - droppedBefore, 0.0);

        for (int i = 0; i < 30; ++i) {
            fed += feed(clock, H, stepper);
        }
        assertConserved(clock, fed);
        assertEquals(clock.getSimulatedSeconds(), stepper.totalSeconds, ACCOUNTING_TOLERANCE);
        assertTrue(stepper.particle.isFinite(), stepper.particle.toString());
    }

    @Test
    void stepCapLimitsStepsPerFrameAndDropsTheWholeStepsItCannotTake() {
        SimulationClock clock = new SimulationClock();
        clock.setMaxStepsPerFrame(4);
        RecordingStepper stepper = new RecordingStepper();

        int steps = clock.advance(0.25f, stepper);

        assertEquals(4, steps);
        // 0.25 s is 15 steps: 4 taken, 11 dropped, the leftover within round-off of zero.
        assertEquals(11.0 * H, clock.getDroppedSeconds(), ACCOUNTING_TOLERANCE);
        assertLeftoverInRange(clock);
        assertConserved(clock, 0.25);
    }

    @Test
    void framesLongerThanAStepButWithinTheCapsLoseNoTime() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        float[] frames = {0.1f, 0.003f, 0.2f, 0.05f, 0.011f, 0.24f, 0.0167f};
        double fed = 0.0;

        for (float frame : frames) {
            fed += feed(clock, frame, stepper);
            assertLeftoverInRange(clock);
        }

        assertEquals(0.0, clock.getDroppedSeconds(), 0.0);
        assertConserved(clock, fed);
    }

    @Test
    void rawModeTakesOneStepOfExactlyTheScaledFrameTime() {
        SimulationClock clock = new SimulationClock();
        clock.setMode(SimulationClock.Mode.RAW_TPF);
        clock.setTimeScale(0.5f);
        RecordingStepper stepper = new RecordingStepper();

        int steps = clock.advance(0.037f, stepper);

        assertEquals(1, steps);
        assertEquals(1, stepper.steps);
        assertEquals(0.037f * 0.5f, stepper.lastSeconds, 0f);
        assertEquals(0.037f * 0.5f, clock.getCurrentStepSeconds(), 0f);
        assertEquals(0.037f * 0.5f, clock.getLastStepSeconds(), 0f);
    }

    @Test
    void rawModePassesAHitchStraightIntoThePhysics() {
        // That is what the mode is for: one 0.5 s frame at k = 5/s multiplies V by 1 − 2.5.
        SimulationClock clock = new SimulationClock();
        clock.setMode(SimulationClock.Mode.RAW_TPF);
        RecordingStepper stepper = RecordingStepper.withParticle(
                new ParticleIntegrator(new LinearDrag(5f)));
        stepper.particle.velocity.set(1f, 0f, 0f);

        assertEquals(1, clock.advance(0.5f, stepper));

        assertEquals(0.5f, stepper.lastSeconds, 0f);
        assertEquals(-1.5f, stepper.particle.velocity.x, 1e-6f);
        assertEquals(0.0, clock.getDroppedSeconds(), 0.0);
    }

    @ParameterizedTest(name = "{1} frames of 1/{0} s take {2} steps of 1/60 s")
    @CsvSource({"90, 3, 2", "100, 5, 3", "120, 2, 1", "144, 12, 5", "50, 5, 6", "30, 1, 2",
        "240, 4, 1", "75, 5, 4"})
    void leftoverIsCarriedAcrossFrames(int framesPerSecond, int frames, int expectedSteps) {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        float tpf = 1f / framesPerSecond;
        double fed = 0.0;

        for (int i = 0; i < frames; ++i) {
            fed += feed(clock, tpf, stepper);
        }

        // The frames add up to whole steps; in float only to round-off, which must not delay
        // the last step to the next frame.
        assertEquals(expectedSteps, stepper.steps);
        assertEquals(0.0, clock.getLeftoverSeconds(), -LEFTOVER_FLOOR);
        assertConserved(clock, fed);
    }

    @Test
    void ninetyHertzFramesAtSixtyHertzStepsFollowTheZeroOneOnePattern() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        int[] stepsPerFrame = new int[9];

        for (int i = 0; i < stepsPerFrame.length; ++i) {
            stepsPerFrame[i] = clock.advance(1f / 90f, stepper);
        }

        assertArrayEquals(new int[] {0, 1, 1, 0, 1, 1, 0, 1, 1}, stepsPerFrame);
        assertEquals(H, stepper.lastSeconds, 0f);
    }

    @Test
    void pausedClockTakesNoStepAndCountsNoTime() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        clock.advance(0.01f, stepper);
        double leftover = clock.getLeftoverSeconds();
        clock.setPaused(true);

        for (int i = 0; i < 10; ++i) {
            assertEquals(0, clock.advance(0.1f, stepper));
        }

        assertTrue(clock.isPaused());
        assertEquals(0, stepper.steps);
        assertEquals(0.0, clock.getSimulatedSeconds(), 0.0);
        assertEquals(leftover, clock.getLeftoverSeconds(), 0.0);
    }

    @ParameterizedTest
    @ValueSource(strings = {"FIXED_STEP", "RAW_TPF"})
    void singleStepWhilePausedTakesExactlyOneStepOfH(SimulationClock.Mode mode) {
        SimulationClock clock = new SimulationClock();
        clock.setMode(mode);
        clock.setStepSeconds(0.02f);
        clock.setPaused(true);
        RecordingStepper stepper = new RecordingStepper();

        clock.requestSingleStep();
        int first = clock.advance(0.5f, stepper);
        int second = clock.advance(0.5f, stepper);

        assertEquals(1, first);
        assertEquals(0, second);
        assertEquals(1, stepper.steps);
        assertEquals(0.02f, stepper.lastSeconds, 0f);
        assertEquals(0.02f, clock.getSimulatedSeconds(), 0.0);
    }

    @Test
    void singleStepRequestWhileRunningIsIgnored() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();

        clock.requestSingleStep();
        assertEquals(1, clock.advance(H, stepper));
        clock.setPaused(true);
        assertEquals(0, clock.advance(H, stepper));

        assertEquals(1, stepper.steps);
    }

    @ParameterizedTest
    @ValueSource(strings = {"FIXED_STEP", "RAW_TPF"})
    void zeroFrameTimeTakesNoStep(SimulationClock.Mode mode) {
        SimulationClock clock = new SimulationClock();
        clock.setMode(mode);
        RecordingStepper stepper = new RecordingStepper();

        assertEquals(0, clock.advance(0f, stepper));
        assertEquals(0, clock.advance(-0f, stepper));

        assertEquals(0, stepper.steps);
        assertEquals(0.0, clock.getSimulatedSeconds(), 0.0);
    }

    @ParameterizedTest
    @ValueSource(floats = {-1e-3f, -1f, Float.NaN, Float.POSITIVE_INFINITY,
        Float.NEGATIVE_INFINITY})
    void rejectsFrameTimeThatIsNegativeOrNotFinite(float bad) {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> clock.advance(bad, stepper));

        String message = thrown.getMessage();
        assertTrue(message.contains("tpf") && message.contains(String.valueOf(bad))
                && message.contains("finite") && message.contains(">= 0"), message);
        assertEquals(0, stepper.steps);
        assertEquals(0.0, clock.getLeftoverSeconds(), 0.0);
    }

    @Test
    void timeScaleMultipliesEveryFrame() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();

        clock.setTimeScale(2f);
        assertEquals(2, clock.advance(H, stepper));
        clock.setTimeScale(0.5f);
        assertEquals(0, clock.advance(H, stepper));
        assertEquals(1, clock.advance(H, stepper));

        assertEquals(3.0 * H, clock.getSimulatedSeconds(), ACCOUNTING_TOLERANCE);
    }

    @Test
    void timeScaleAcceptsItsLimits() {
        SimulationClock clock = new SimulationClock();

        clock.setTimeScale(SimulationClock.MIN_TIME_SCALE);
        assertEquals(SimulationClock.MIN_TIME_SCALE, clock.getTimeScale(), 0f);
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        assertEquals(SimulationClock.MAX_TIME_SCALE, clock.getTimeScale(), 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {0f, -1f, 1f / 128f, 65f, Float.NaN, Float.POSITIVE_INFINITY})
    void timeScaleRejectsValuesOutsideItsLimitsNamingThem(float bad) {
        SimulationClock clock = new SimulationClock();

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> clock.setTimeScale(bad));

        String message = thrown.getMessage();
        assertTrue(message.contains("time scale") && message.contains(String.valueOf(bad))
                && message.contains(String.valueOf(SimulationClock.MIN_TIME_SCALE))
                && message.contains(String.valueOf(SimulationClock.MAX_TIME_SCALE)), message);
        assertEquals(1f, clock.getTimeScale(), 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {0f, -0.01f, Float.NaN, Float.POSITIVE_INFINITY})
    void secondsSettersRejectValuesThatAreNotFiniteAndPositive(float bad) {
        SimulationClock clock = new SimulationClock();

        IllegalArgumentException step = assertThrows(IllegalArgumentException.class,
                () -> clock.setStepSeconds(bad));
        IllegalArgumentException frame = assertThrows(IllegalArgumentException.class,
                () -> clock.setMaxFrameSeconds(bad));

        assertTrue(step.getMessage().contains("fixed step h")
                && step.getMessage().contains(String.valueOf(bad)), step.getMessage());
        assertTrue(frame.getMessage().contains("max frame time")
                && frame.getMessage().contains("> 0"), frame.getMessage());
        assertEquals(H, clock.getStepSeconds(), 0f);
        assertEquals(SimulationClock.DEFAULT_MAX_FRAME_SECONDS, clock.getMaxFrameSeconds(), 0f);
    }

    @Test
    void otherSettersRejectBadValues() {
        SimulationClock clock = new SimulationClock();

        IllegalArgumentException cap = assertThrows(IllegalArgumentException.class,
                () -> clock.setMaxStepsPerFrame(0));
        assertTrue(cap.getMessage().contains("max steps per frame")
                && cap.getMessage().contains(">= 1"), cap.getMessage());
        assertThrows(IllegalArgumentException.class, () -> clock.setMode(null));

        assertEquals(SimulationClock.DEFAULT_MAX_STEPS_PER_FRAME, clock.getMaxStepsPerFrame());
        assertSame(SimulationClock.Mode.FIXED_STEP, clock.getMode());
    }

    @Test
    void toggleModeSwitchesAndResetForgetsTimeButKeepsSettings() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        clock.setStepSeconds(0.01f);
        clock.setTimeScale(2f);
        clock.advance(5f, stepper);
        clock.setPaused(true);

        clock.toggleMode();
        assertSame(SimulationClock.Mode.RAW_TPF, clock.getMode());
        clock.reset();

        assertEquals(0.0, clock.getSimulatedSeconds(), 0.0);
        assertEquals(0.0, clock.getDroppedSeconds(), 0.0);
        assertEquals(0.0, clock.getLeftoverSeconds(), 0.0);
        assertEquals(0f, clock.getLastStepSeconds(), 0f);
        assertSame(SimulationClock.Mode.RAW_TPF, clock.getMode());
        assertEquals(0.01f, clock.getStepSeconds(), 0f);
        assertEquals(2f, clock.getTimeScale(), 0f);
        assertTrue(clock.isPaused());
        clock.toggleMode();
        assertSame(SimulationClock.Mode.FIXED_STEP, clock.getMode());
    }

    @Test
    void aResetFromInsideTheStepperInItsThirdStepLeavesTheClockAtZero() {
        // A scene that restarts itself during a step (demo 1 at the screen's edge).
        SimulationClock clock = new SimulationClock();
        int[] calls = {0};
        SimulationClock.Stepper resetsInThirdStep = seconds -> {
            if (++calls[0] == 3) {
                clock.reset();
            }
        };

        // Five steps' worth of frame time: the reset in the third ends the frame.
        int steps = clock.advance(5 * H, resetsInThirdStep);

        assertEquals(3, steps);
        assertEquals(3, calls[0]);
        assertEquals(0.0, clock.getSimulatedSeconds(), 0.0);
        assertEquals(0.0, clock.getLeftoverSeconds(), 0.0);
        assertEquals(0.0, clock.getDroppedSeconds(), 0.0);
        assertEquals(0f, clock.getLastStepSeconds(), 0f);
        assertLeftoverInRange(clock);
        // The next frame of h takes exactly one step, counted from zero.
        assertEquals(1, clock.advance(H, resetsInThirdStep));
        assertEquals(H, clock.getSimulatedSeconds(), 0.0);
        assertEquals(0.0, clock.getLeftoverSeconds(), -LEFTOVER_FLOOR);
    }

    @Test
    void aPauseFromInsideTheStepperEndsTheFrameAfterThatStepAndResumesWithoutABurst() {
        // A demo that stops at a contact found in the third of a frame's five steps.
        SimulationClock clock = new SimulationClock();
        int[] calls = {0};
        SimulationClock.Stepper pausesInThirdStep = seconds -> {
            if (++calls[0] == 3) {
                clock.setPaused(true);
            }
        };
        double fed = 5.5 * H;

        int steps = clock.advance((float) fed, pausesInThirdStep);

        assertEquals(3, steps);
        assertEquals(3, calls[0]);
        assertTrue(clock.isPaused());
        // The step that paused is counted: t is the end of the third step, not of the frame
        // (three float steps summed in double: exact to ~1e-16, see ACCOUNTING_TOLERANCE).
        assertEquals(3.0 * H, clock.getSimulatedSeconds(), ACCOUNTING_TOLERANCE);
        assertLeftoverInRange(clock);
        assertConserved(clock, (float) fed);
        // Frames keep coming: nothing more is simulated.
        for (int i = 0; i < 10; ++i) {
            assertEquals(0, clock.advance(H, pausesInThirdStep));
        }
        assertEquals(3.0 * H, clock.getSimulatedSeconds(), ACCOUNTING_TOLERANCE);
        // Resumed, a frame of h takes one step: the two steps the pause cut off are dropped.
        clock.setPaused(false);
        assertEquals(1, clock.advance(H, pausesInThirdStep));
        assertEquals(4.0 * H, clock.getSimulatedSeconds(), ACCOUNTING_TOLERANCE);
        assertFalse(clock.isDroppingTime(), "a pause is not the clamp or the cap");
    }

    @Test
    void aResetFromInsideARawStepIsNotCountedEither() {
        SimulationClock clock = new SimulationClock();
        clock.setMode(SimulationClock.Mode.RAW_TPF);

        assertEquals(1, clock.advance(0.04f, seconds -> clock.reset()));

        assertEquals(0.0, clock.getSimulatedSeconds(), 0.0);
        assertEquals(0f, clock.getLastStepSeconds(), 0f);
        assertEquals(1, clock.advance(0.04f, new RecordingStepper()));
        assertEquals(0.04f, clock.getSimulatedSeconds(), 0.0);
    }

    @Test
    void switchingModesCountsTheLeftoverAsDropped() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        double fed = feed(clock, 0.03f, stepper); // one step of 1/60 s, 0.0133 s left over
        double leftover = clock.getLeftoverSeconds();
        assertTrue(leftover > 0.0, "leftover " + leftover);

        clock.toggleMode();

        assertEquals(0.0, clock.getLeftoverSeconds(), 0.0);
        assertEquals(leftover, clock.getDroppedSeconds(), 0.0);
        clock.toggleMode();
        for (int i = 0; i < 7; ++i) {
            fed += feed(clock, 0.021f, stepper);
        }
        assertConserved(clock, fed);
    }

    @ParameterizedTest(name = "x64 asked at {0} fps runs at x{1}")
    @CsvSource({"23, 5.75", "60, 15"})
    void measuredTimeScaleShowsWhatTheClampLeavesOfTheAskedScale(int framesPerSecond,
            float expected) {
        // The numbers: a frame simulates at most 0.25 s, so x64 becomes 0.25 s per
        // frame time (0.25·23 = 5.75, 0.25·60 = 15). Every clamped frame is 15 whole steps
        // (up to the round-off the clock tolerates), so the ratio is exact to float.
        SimulationClock clock = new SimulationClock();
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        RecordingStepper stepper = new RecordingStepper();
        float tpf = 1f / framesPerSecond;
        assertTrue(Float.isNaN(clock.getMeasuredTimeScale()));

        for (int i = 0; i < 2 * framesPerSecond; ++i) {
            clock.advance(tpf, stepper);
        }

        assertEquals(expected, clock.getMeasuredTimeScale(), 1e-4f);
        assertEquals(expected, clock.getMaxMeasurableTimeScale(), 1e-4f);
        assertEquals(tpf, clock.getMeasuredFrameSeconds(), 1e-6f);
        assertTrue(clock.isDroppingTime());
    }

    @Test
    void theSlowestScaleIsMeasuredOverEnoughSteps() {
        // x1/64 at h = 1/60 s and 60 fps: one step every 64 frames (1.07 s), so a 0.5 s window
        // held 0 or 1 step and read x0.00 or x0.03. A window of at least RATE_WINDOW_STEPS
        // steps may hold one step more or less than its frame time: within 1/8 of x1/64.
        SimulationClock clock = new SimulationClock();
        clock.setTimeScale(SimulationClock.MIN_TIME_SCALE);
        RecordingStepper stepper = new RecordingStepper();
        float asked = SimulationClock.MIN_TIME_SCALE;
        int measured = 0;
        for (int i = 0; i < 60 * 120; ++i) {
            clock.advance(H, stepper);
            float rate = clock.getMeasuredTimeScale();
            if (!Float.isNaN(rate)) {
                ++measured;
                assertEquals(asked, rate, asked / SimulationClock.RATE_WINDOW_STEPS,
                        "frame " + i);
            }
        }
        assertTrue(measured > 0);
    }

    @Test
    void measuredTimeScaleFollowsTheAskedScaleWithinItsLimitsAndIsZeroWhilePaused() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        clock.setTimeScale(4f);
        for (int i = 0; i < 120; ++i) {
            clock.advance(H, stepper);
        }
        // Four whole steps a frame: exact to float.
        assertEquals(4f, clock.getMeasuredTimeScale(), 1e-4f);
        assertFalse(clock.isDroppingTime());

        // 144 Hz frames at x1: steps are whole, so a window of ~0.5 s may hold one step more
        // or less than its frame time; the ratio is off by at most h / 0.5 s.
        clock.setTimeScale(1f);
        for (int i = 0; i < 144; ++i) {
            clock.advance(1f / 144f, stepper);
        }
        assertEquals(1f, clock.getMeasuredTimeScale(), H / SimulationClock.RATE_WINDOW_SECONDS);
        assertFalse(clock.isDroppingTime());

        clock.setPaused(true);
        for (int i = 0; i < 60; ++i) {
            clock.advance(H, stepper);
        }
        assertEquals(0f, clock.getMeasuredTimeScale(), 0f);
    }

    @Test
    void changingTheScaleStartsTheMeasurementAgain() {
        SimulationClock clock = new SimulationClock();
        RecordingStepper stepper = new RecordingStepper();
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        for (int i = 0; i < 60; ++i) {
            clock.advance(H, stepper);
        }
        assertTrue(clock.isDroppingTime());

        clock.setTimeScale(1f);

        // Neither x15 nor "dropping" outlives the settings they were measured under.
        assertTrue(Float.isNaN(clock.getMeasuredTimeScale()));
        assertFalse(clock.isDroppingTime());
        for (int i = 0; i < 30; ++i) {
            clock.advance(H, stepper);
        }
        assertEquals(1f, clock.getMeasuredTimeScale(), H / SimulationClock.RATE_WINDOW_SECONDS);
    }

    @Test
    void rawModeHasNoFrameLimitAndDropsNothing() {
        SimulationClock clock = new SimulationClock();
        clock.setMode(SimulationClock.Mode.RAW_TPF);
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        RecordingStepper stepper = new RecordingStepper();
        for (int i = 0; i < 60; ++i) {
            clock.advance(H, stepper);
        }
        assertEquals(SimulationClock.MAX_TIME_SCALE, clock.getMeasuredTimeScale(), 1e-3f);
        assertEquals(Float.POSITIVE_INFINITY, clock.getMaxMeasurableTimeScale(), 0f);
        assertFalse(clock.isDroppingTime());
    }

    /** Advance one frame and return the scaled time fed, for the accounting checks. */
    private static double feed(SimulationClock clock, float tpf, RecordingStepper stepper) {
        int steps = clock.advance(tpf, stepper);
        assertTrue(steps <= clock.getMaxStepsPerFrame(), steps + " steps in one frame");
        return tpf * clock.getTimeScale();
    }

    /** Simulated + dropped + leftover == fed, in fixed-step mode without single steps. */
    private static void assertConserved(SimulationClock clock, double fedSeconds) {
        double accounted = clock.getSimulatedSeconds() + clock.getDroppedSeconds()
                + clock.getLeftoverSeconds();
        assertEquals(fedSeconds, accounted, ACCOUNTING_TOLERANCE, "simulated + dropped + leftover");
    }

    private static void assertLeftoverInRange(SimulationClock clock) {
        double leftover = clock.getLeftoverSeconds();
        assertTrue(leftover >= LEFTOVER_FLOOR && leftover < clock.getStepSeconds(),
                "leftover " + leftover);
    }

    /** Counts the steps it is given and, if it has one, steps a particle with them. */
    private static final class RecordingStepper implements SimulationClock.Stepper {
        final Particle particle = new Particle();
        private final ParticleIntegrator integrator;
        int steps;
        float lastSeconds;
        double totalSeconds;

        RecordingStepper() {
            this(null);
        }

        private RecordingStepper(ParticleIntegrator integrator) {
            this.integrator = integrator;
            particle.velocity.set(10f, 10f, 0f);
        }

        static RecordingStepper withParticle(ParticleIntegrator integrator) {
            return new RecordingStepper(integrator);
        }

        @Override
        public void step(float stepSeconds) {
            ++steps;
            lastSeconds = stepSeconds;
            totalSeconds += stepSeconds;
            if (integrator != null) {
                integrator.step(particle, stepSeconds);
            }
        }
    }
}
