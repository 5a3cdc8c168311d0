package particlelab.bench;

import com.jme3.math.Vector3f;
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
import particlelab.accuracy.LectureStyleParticle;
import particlelab.accuracy.PrimitiveLoop;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * Many particles under gravity and linear drag (b/m = 0.5/s, h = 1/60 s), one step of all of
 * them per invocation: lecture-style objects, Particle objects through the shared integrator,
 * the integrator's packed batch form, and the primitive loop. The score is per invocation;
 * the runner divides it (and the bytes allocated) by the particle count.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Thread)
public class BulkBenchmark {

    private static final float STEP_SECONDS = 1f / 60f;
    private static final float LINEAR_RATE = 0.5f;

    /** The number of particles. */
    @Param({"1000", "10000", "100000", "1000000"})
    public int particles;

    private final ParticleIntegrator integrator =
            new ParticleIntegrator(new Gravity(), new LinearDrag(LINEAR_RATE));
    private final Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    private final float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};

    private LectureStyleParticle[] lecture;
    private Particle[] objects;
    private float[] positions;
    private float[] velocities;

    /** Launch every particle at a slightly different velocity, once per trial. */
    @Setup(Level.Trial)
    public void launch() {
        lecture = new LectureStyleParticle[particles];
        objects = new Particle[particles];
        positions = new float[3 * particles];
        velocities = new float[3 * particles];
        for (int i = 0; i < particles; ++i) {
            Vector3f velocity = new Vector3f(20f + i % 7, 30f + i % 11, i % 5);
            lecture[i] = new LectureStyleParticle(new Vector3f(), velocity, 1f);
            objects[i] = new Particle(new Vector3f(), velocity, 1f);
            velocities[i] = velocity.x;
            velocities[particles + i] = velocity.y;
            velocities[2 * particles + i] = velocity.z;
        }
    }

    @Benchmark
    public Object lectureStyle() {
        for (int i = 0; i < particles; ++i) {
            lecture[i].step(gravity, LINEAR_RATE, STEP_SECONDS);
        }
        return lecture;
    }

    @Benchmark
    public Object sharedObjects() {
        integrator.step(objects, STEP_SECONDS);
        return objects;
    }

    @Benchmark
    public Object sharedBatch() {
        integrator.stepPacked(positions, velocities, particles, 1f, STEP_SECONDS);
        return positions;
    }

    @Benchmark
    public Object primitiveLoop() {
        PrimitiveLoop.step(positions, velocities, particles, gravityPerAxis, LINEAR_RATE,
                STEP_SECONDS);
        return positions;
    }
}
