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
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleBatch;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Fountain;

/**
 * The fountain's whole physics step ({@link Fountain#step}: the Euler step of the particles in
 * flight, the ground, the lifecycle, the fireworks and new water) against the bare batch step
 * ({@link ParticleBatch#stepPacked}) of the same N particles under the same forces (rows
 * {@code bulk/fountain-step/<N>} and {@code bulk/fountain-step-packed/<N>}, per particle of
 * the pool). The fountain runs {@value #FLOW_STEPS} steps first, so it is in full flow (about
 * 89 % of the pool in flight); the bare step moves a copy of that state, every particle of it,
 * and starts again from the copy every {@value #STEPS_PER_COPY} steps, so nothing falls far
 * enough to change the arithmetic (no subnormal floats: the drag keeps |V| near 49 m/s at
 * most).
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Thread)
public class FountainBenchmark {

    /** Steps before timing: the fountain fills its pool. */
    static final int FLOW_STEPS = 900;
    /** The bare step's state is restored from the copy this often. */
    static final int STEPS_PER_COPY = 600;
    private static final float STEP_SECONDS = 1f / 60f;

    /** The pool size N. */
    @Param({"10000", "100000", "1000000"})
    public int particles;

    private Fountain fountain;
    private final ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
            new LinearDrag(Fountain.DRAG_B));
    private float[] startPositions;
    private float[] startVelocities;
    private float[] positions;
    private float[] velocities;
    private int steps;

    /** Fill the fountain and copy its state for the bare step. */
    @Setup(Level.Trial)
    public void flow() {
        fountain = new Fountain(particles);
        for (int i = 0; i < FLOW_STEPS; ++i) {
            fountain.step(STEP_SECONDS);
        }
        startPositions = fountain.getPositions().clone();
        startVelocities = fountain.getVelocities().clone();
        positions = startPositions.clone();
        velocities = startVelocities.clone();
    }

    /**
     * One whole step of the fountain.
     *
     * @return something the caller must consume
     */
    @Benchmark
    public Object fountainStep() {
        fountain.step(STEP_SECONDS);
        return fountain;
    }

    /**
     * One bare batch step of all N particles.
     *
     * @return something the caller must consume
     */
    @Benchmark
    public Object fountainStepPacked() {
        if (++steps == STEPS_PER_COPY) {
            steps = 0;
            System.arraycopy(startPositions, 0, positions, 0, positions.length);
            System.arraycopy(startVelocities, 0, velocities, 0, velocities.length);
        }
        integrator.batch().stepPacked(positions, velocities, particles, Fountain.MASS_KG,
                STEP_SECONDS);
        return positions;
    }
}
