package particlelab.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import particlelab.accuracy.BulkScene;

/**
 * Many particles under gravity and linear drag ({@link BulkScene}: b/m = 0.5/s, h = 1/60 s),
 * one step of all of them per invocation: lecture-style objects, Particle objects through the
 * shared integrator, the integrator's packed batch form, and the primitive loop. The scene
 * relaunches itself every {@value BulkScene#STEPS_PER_LAUNCH} steps, so no velocity decays into
 * subnormal floats however long JMH runs. The score is per invocation; the runner divides it
 * (and the bytes allocated) by the particle count.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Thread)
public class BulkBenchmark {

    /** The number of particles. */
    @Param({"1000", "10000", "100000", "1000000"})
    public int particles;

    private BulkScene scene;

    /** Launch every particle at a slightly different velocity, once per trial. */
    @Setup(Level.Trial)
    public void launch() {
        scene = new BulkScene(particles);
    }

    @Benchmark
    public Object lectureStyle() {
        return scene.stepLectureStyle();
    }

    @Benchmark
    public Object sharedObjects() {
        return scene.stepSharedObjects();
    }

    @Benchmark
    public Object sharedBatch() {
        return scene.stepSharedBatch();
    }

    @Benchmark
    public Object primitiveLoop() {
        return scene.stepPrimitiveLoop();
    }
}
