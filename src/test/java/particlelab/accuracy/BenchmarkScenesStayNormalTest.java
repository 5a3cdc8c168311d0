package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.physics.Particle;
import particlelab.reference.MotionState;
import particlelab.reference.Scheme;
import particlelab.reference.Stepper;


/**
 * Every benchmark scene keeps its state in the normal float range however long a measurement
 * runs (x86 arithmetic on subnormals is 30–40× slower, so a scene that decays into them
 * measures the wrong thing). Each scene is run well past the point where a never-relaunched
 * flight goes subnormal, and every component is checked. Not a timing.
 */
class BenchmarkScenesStayNormalTest {

    /**
     * Steps each scene is run for: four times the ~1.08e4 steps after which vx = 26 m/s, the
     * fastest launch, decays below {@link Float#MIN_NORMAL} at (1 − h·b/m) = 1 − 1/120 per step.
     */
    private static final int STEPS = 44_000;
    /** Enough particles for every launch of BulkScene (i mod 7, 11 and 5: lcm 385). */
    private static final int PARTICLES = 385;

    @Test
    void bulkSceneLectureStyleStaysNormal() {
        BulkScene scene = new BulkScene(PARTICLES);
        float[] state = new float[6 * PARTICLES];
        for (int n = 1; n <= STEPS; ++n) {
            scene.stepLectureStyle();
            scene.copyLectureStyle(state);
            assertNormal(state, "lecture style after " + n + " steps");
        }
    }

    @Test
    void bulkSceneObjectsStayNormal() {
        BulkScene scene = new BulkScene(PARTICLES);
        float[] state = new float[6 * PARTICLES];
        for (int n = 1; n <= STEPS; ++n) {
            scene.stepSharedObjects();
            scene.copyObjects(state);
            assertNormal(state, "Particle objects after " + n + " steps");
        }
    }

    @Test
    void bulkScenePackedArraysStayNormalUnderBothPackedForms() {
        BulkScene scene = new BulkScene(PARTICLES);
        float[] state = new float[6 * PARTICLES];
        // the batch form and the primitive loop share the arrays and their relaunch schedule
        for (int n = 1; n <= STEPS; ++n) {
            if (n < STEPS / 2) {
                scene.stepSharedBatch();
            } else {
                scene.stepPrimitiveLoop();
            }
            scene.copyPacked(state);
            assertNormal(state, "packed arrays after " + n + " steps");
        }
    }

    @ParameterizedTest
    @EnumSource(ForceMix.class)
    void bulkSceneOfEveryMixStaysNormalAlongEveryPath(ForceMix mix) {
        BulkScene scene = new BulkScene(mix, PARTICLES);
        float[] state = new float[6 * PARTICLES];
        for (int n = 1; n <= STEPS; ++n) {
            scene.stepLectureStyle();
            scene.copyLectureStyle(state);
            assertNormal(state, mix.id() + " lecture style after " + n + " steps");
        }
        // step(Particle, h) each, the array form and the bookkeeping share the objects
        for (int n = 1; n <= STEPS; ++n) {
            if (n % 3 == 0) {
                scene.stepSharedEach();
            } else if (n % 3 == 1) {
                scene.stepSharedObjects();
            } else {
                scene.stepSharedEachWithRegime();
            }
            scene.copyObjects(state);
            assertNormal(state, mix.id() + " Particle objects after " + n + " steps");
        }
        for (int n = 1; n <= STEPS; ++n) {
            if (n < STEPS / 2) {
                scene.stepSharedBatch();
            } else {
                scene.stepPrimitiveLoop();
            }
            scene.copyPacked(state);
            assertNormal(state, mix.id() + " packed arrays after " + n + " steps");
        }
    }

    @ParameterizedTest
    @EnumSource(ForceMix.class)
    void oneParticleMixSceneStaysNormalAlongEveryPath(ForceMix mix) {
        OneParticleMixScene scene = new OneParticleMixScene(mix);
        // Whole flights inside one call: only each flight's end is seen. Along x and z the
        // factor 1 − h·σ stays positive (h·σ ≤ 0.012 for these mixes), so vx and vz keep
        // their sign and shrink, or (thrust, below the cruise speed) first grow and then
        // shrink: their smallest value in a flight is at its start or at its end, which is
        // checked. vy crosses zero in steps of about g·h.
        for (int calls = 0; calls * OneParticleMixScene.STEPS_PER_LAUNCH < STEPS; ++calls) {
            LectureStyleParticle lecture = scene.flyLectureStyle();
            assertNormal(new float[] {lecture.position.x, lecture.position.y,
                lecture.position.z, lecture.velocity.x, lecture.velocity.y, lecture.velocity.z},
                    mix.id() + " lecture style after flight " + calls);
            Particle particle = scene.flySharedObjects();
            assertNormal(new float[] {particle.position.x, particle.position.y,
                particle.position.z, particle.velocity.x, particle.velocity.y,
                particle.velocity.z}, mix.id() + " shared objects after flight " + calls);
            scene.flySharedWithRegime();
            assertNormal(new float[] {particle.position.x, particle.position.y,
                particle.position.z, particle.velocity.x, particle.velocity.y,
                particle.velocity.z}, mix.id() + " with regime after flight " + calls);
            float[] position = scene.flyPrimitiveLoop();
            assertNormal(position, mix.id() + " primitive loop P after flight " + calls);
            assertNormal(scene.primitiveVelocity(), mix.id() + " primitive loop V after flight "
                    + calls);
        }
    }

    @Test
    void bulkSceneRepeatsItsFirstFlightAfterEveryRelaunch() {
        // Periodic state means any measurement, however long, only ever sees the states
        // checked above: the step after k relaunches equals the very first step, bit for bit.
        int laterStep = 3 * BulkScene.STEPS_PER_LAUNCH + 1;
        BulkScene first = new BulkScene(PARTICLES);
        BulkScene later = new BulkScene(PARTICLES);
        first.stepLectureStyle();
        first.stepSharedObjects();
        first.stepSharedBatch();
        for (int n = 0; n < laterStep; ++n) {
            later.stepLectureStyle();
            later.stepSharedObjects();
            later.stepSharedBatch();
        }
        float[] expected = new float[6 * PARTICLES];
        float[] actual = new float[6 * PARTICLES];
        first.copyLectureStyle(expected);
        later.copyLectureStyle(actual);
        assertArrayEquals(expected, actual, "lecture style");
        first.copyObjects(expected);
        later.copyObjects(actual);
        assertArrayEquals(expected, actual, "Particle objects");
        first.copyPacked(expected);
        later.copyPacked(actual);
        assertArrayEquals(expected, actual, "packed arrays");
    }

    @ParameterizedTest
    @EnumSource(Scheme.class)
    void oneParticleSceneStaysNormalWithEveryStepper(Scheme scheme) {
        OneParticleScene scene = new OneParticleScene();
        CheckingStepper checking = new CheckingStepper(scheme.create(scene.forces()));
        for (int calls = 0; calls * OneParticleScene.STEPS_PER_LAUNCH < STEPS; ++calls) {
            scene.fly(checking);
        }
        assertEquals(STEPS, checking.steps, "every step was checked");
    }

    @Test
    void oneParticleSceneStaysNormalInTheLectureStyleAndThePrimitiveLoop() {
        OneParticleScene scene = new OneParticleScene();
        // Both fly whole flights inside one call, so only the end of each flight is seen. Each
        // component moves monotonically toward terminal velocity (vx → 0, vy → −g·m/b), so
        // the end of a flight is where vx is smallest; vy crosses zero in steps of g·h.
        for (int calls = 0; calls * OneParticleScene.STEPS_PER_LAUNCH < STEPS; ++calls) {
            LectureStyleParticle lecture = scene.flyLectureStyle();
            assertNormal(new float[] {lecture.position.x, lecture.position.y,
                lecture.position.z, lecture.velocity.x, lecture.velocity.y, lecture.velocity.z},
                    "lecture style after flight " + calls);
            float[] position = scene.flyPrimitiveLoop();
            assertNormal(position, "primitive loop P after flight " + calls);
            assertNormal(scene.primitiveVelocity(), "primitive loop V after flight " + calls);
        }
    }

    @ParameterizedTest
    @EnumSource(Scheme.class)
    void workPrecisionTimingFlightsStayNormalInEveryCase(Scheme scheme) {
        for (CanonicalCase scene : CanonicalCase.all()) {
            if (!scheme.supports(scene.forces())) {
                continue;
            }
            CheckingStepper checking = new CheckingStepper(scheme.create(scene.forces()));
            MotionState state = new MotionState();
            for (int calls = 0; calls * WorkPrecisionStudy.STEPS_PER_TIMING_CALL < STEPS;
                    ++calls) {
                WorkPrecisionStudy.timingFlight(checking, CanonicalCase.launch(), state);
            }
        }
    }

    private static void assertNormal(float[] values, String what) {
        for (int i = 0; i < values.length; ++i) {
            if (isSubnormal(values[i])) {
                fail(what + ": component " + i + " is subnormal: " + values[i]);
            }
        }
    }

    /**
     * Test a number against the float range, also for double states: a double below
     * {@link Float#MIN_NORMAL} is a subnormal float in the shared integrator's own run, and
     * far below any velocity a benchmark means to measure.
     */
    private static boolean isSubnormal(double value) {
        return value != 0.0 && Math.abs(value) < Float.MIN_NORMAL;
    }

    /** Takes every step one at a time and checks the state after each. */
    private static final class CheckingStepper implements Stepper {
        private final Stepper inner;
        private int steps;

        CheckingStepper(Stepper inner) {
            this.inner = inner;
        }

        @Override
        public Scheme scheme() {
            return inner.scheme();
        }

        @Override
        public void step(MotionState state, double stepSeconds) {
            inner.step(state, stepSeconds);
            ++steps;
            for (int axis = 0; axis < 3; ++axis) {
                if (isSubnormal(state.position[axis]) || isSubnormal(state.velocity[axis])) {
                    fail(inner.scheme().id() + " after " + steps + " steps: " + state);
                }
            }
        }

        @Override
        public void advance(MotionState state, double stepSeconds, int count) {
            for (int n = 0; n < count; ++n) {
                step(state, stepSeconds);
            }
        }
    }
}
