package particlelab.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import particlelab.accuracy.BulkScene;
import particlelab.accuracy.ForceMix;
import particlelab.accuracy.OneParticleMixScene;

/**
 * The shared integrator for every force mix of the demos ({@link ForceMix}: {@code gravity},
 * {@code linear}, {@code quadratic}, {@code thrust-linear}), against a hand-written primitive
 * float loop for the same mix and against the lecture's allocating {@code Vector3f} style, on
 * the report's own scenes, so both time the same thing. Scores are per particle-step; the
 * runner names the rows as the report does.
 *
 * <ul>
 * <li>{@code single*} ({@link OneParticleMixScene}): one particle,
 * {@value OneParticleMixScene#STEPS_PER_LAUNCH} dependent steps per invocation (latency): rows
 * {@code single/<mix>/<path>}; {@code singleSharedObjectsRegime} adds the stability
 * bookkeeping the demos do every step ({@code regime}).</li>
 * <li>{@code bulk*} ({@link BulkScene}): N particles, one step of all of them per invocation:
 * lecture-style objects, Particle objects through {@code step(Particle, h)}, the packed batch
 * {@code stepPacked} (the scalar form the app runs by default) and the primitive loop: rows
 * {@code bulk/<mix>/<path>/<N>} (the score is per invocation; the runner divides it by N);
 * {@code bulkSharedBatchVector}, the batch on the Vector API for gravity and linear drag:
 * rows {@code bulk/<mix>/shared-batch-vector/<N>}.</li>
 * <li>{@code objects*}: {@value #OBJECTS} Particle objects through {@code step(Particle[], h)}
 * and through {@code step(Particle, h)} with the bookkeeping: rows
 * {@code bulk/<mix>/shared-array/1000} and {@code bulk/<mix>/shared-objects-regime/1000}.</li>
 * </ul>
 *
 * <p>Every state stays in the normal float range: both scenes relaunch every
 * {@value BulkScene#STEPS_PER_LAUNCH} steps, long before a velocity component decaying under
 * drag could become subnormal (after about 10^4 steps), where float arithmetic is 30–40 times
 * slower.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class MixBenchmark {

    /** Particles as objects in the {@code objects*} benchmarks. */
    public static final int OBJECTS = 1000;

    private static final int STEPS = OneParticleMixScene.STEPS_PER_LAUNCH;

    /** One particle, flown along every path. */
    @State(Scope.Thread)
    public static class Single {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;

        OneParticleMixScene scene;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            scene = new OneParticleMixScene(ForceMix.named(mix));
        }
    }

    /** N particles, held four ways. */
    @State(Scope.Thread)
    public static class Bulk {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;
        /** N. */
        @Param({"1000", "10000", "100000", "1000000"})
        public int particles;

        BulkScene scene;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            scene = new BulkScene(ForceMix.named(mix), particles);
        }
    }

    /**
     * N particles under the mixes whose batch has a Vector API form ({@code gravity},
     * {@code linear}); the JVM must have the API (the build's jmh task adds it).
     */
    @State(Scope.Thread)
    public static class VectorBulk {
        /** The force mix. */
        @Param({"gravity", "linear"})
        public String mix;
        /** N. */
        @Param({"1000", "10000", "100000", "1000000"})
        public int particles;

        BulkScene scene;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            scene = new BulkScene(ForceMix.named(mix), particles);
        }
    }

    /** {@value #OBJECTS} particles as objects. */
    @State(Scope.Thread)
    public static class ManyObjects {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;

        BulkScene scene;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            scene = new BulkScene(ForceMix.named(mix), OBJECTS);
        }
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singleLectureStyle(Single s) {
        return s.scene.flyLectureStyle();
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singleSharedObjects(Single s) {
        return s.scene.flySharedObjects();
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public int singleSharedObjectsRegime(Single s) {
        return s.scene.flySharedWithRegime();
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singlePrimitiveLoop(Single s) {
        return s.scene.flyPrimitiveLoop();
    }

    @Benchmark
    public Object bulkLectureStyle(Bulk s) {
        return s.scene.stepLectureStyle();
    }

    @Benchmark
    public Object bulkSharedObjects(Bulk s) {
        return s.scene.stepSharedEach();
    }

    @Benchmark
    public Object bulkSharedBatch(Bulk s) {
        return s.scene.stepSharedBatch();
    }

    @Benchmark
    public Object bulkSharedBatchVector(VectorBulk s) {
        return s.scene.stepSharedBatchVector();
    }

    @Benchmark
    public Object bulkPrimitiveLoop(Bulk s) {
        return s.scene.stepPrimitiveLoop();
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public Object objectsSharedArray(ManyObjects s) {
        return s.scene.stepSharedObjects();
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public int objectsSharedObjectsRegime(ManyObjects s) {
        return s.scene.stepSharedEachWithRegime();
    }
}
