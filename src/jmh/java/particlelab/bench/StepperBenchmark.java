package particlelab.bench;

import com.jme3.math.Vector3f;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import particlelab.accuracy.ExactDragStep;
import particlelab.accuracy.ForceModel;
import particlelab.accuracy.ForwardEuler;
import particlelab.accuracy.LectureStyleParticle;
import particlelab.accuracy.MidpointStepper;
import particlelab.accuracy.MotionState;
import particlelab.accuracy.PrimitiveLoop;
import particlelab.accuracy.RungeKutta4;
import particlelab.accuracy.SharedEulerStepper;
import particlelab.accuracy.VelocityVerlet;

/**
 * One particle under gravity and linear drag (b/m = 0.5/s, h = 1/60 s), stepped
 * {@value #STEPS} times per invocation by each stepper and by the two references: the
 * lecture's allocating style and the primitive loop. Scores are per particle-step.
 * Consecutive steps of one particle depend on each other, so these measure latency.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Thread)
public class StepperBenchmark {

    /** Steps per invocation: long enough that JMH's own overhead vanishes. */
    public static final int STEPS = 1000;

    private static final double STEP_SECONDS = 1.0 / 60.0;
    private static final float STEP_FLOAT = 1f / 60f;
    private static final float LINEAR_RATE = 0.5f;

    private final ForceModel forces = ForceModel.perUnitMass(9.8, LINEAR_RATE, 0.0, 0.0);
    // concrete types, so each benchmark calls one known class
    private final ForwardEuler forwardEuler = new ForwardEuler(forces);
    private final SharedEulerStepper semiImplicitEuler = new SharedEulerStepper(forces);
    private final VelocityVerlet velocityVerlet = new VelocityVerlet(forces);
    private final MidpointStepper midpoint = new MidpointStepper(forces);
    private final RungeKutta4 rk4 = new RungeKutta4(forces);
    private final ExactDragStep exact = new ExactDragStep(forces);
    private final Vector3f gravity = new Vector3f(0f, -9.8f, 0f);
    private final float[] gravityPerAxis = {0f, -9.8f, 0f};

    private MotionState state;
    private LectureStyleParticle lecture;
    private float[] positions;
    private float[] velocities;

    /** Start every iteration from the canonical launch. */
    @Setup(Level.Iteration)
    public void launch() {
        state = new MotionState(0.0, 0.0, 20.0, 30.0);
        lecture = new LectureStyleParticle(new Vector3f(), new Vector3f(20f, 30f, 0f), 1f);
        positions = new float[3];
        velocities = new float[] {20f, 30f, 0f};
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState forwardEuler() {
        forwardEuler.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState semiImplicitEuler() {
        semiImplicitEuler.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState velocityVerlet() {
        velocityVerlet.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState midpoint() {
        midpoint.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState rk4() {
        rk4.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState exact() {
        exact.advance(state, STEP_SECONDS, STEPS);
        return state;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public LectureStyleParticle lectureStyle() {
        for (int n = 0; n < STEPS; ++n) {
            lecture.step(gravity, LINEAR_RATE, STEP_FLOAT);
        }
        return lecture;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public float[] primitiveLoop() {
        PrimitiveLoop.stepOne(positions, velocities, gravityPerAxis, LINEAR_RATE, STEP_FLOAT,
                STEPS);
        return positions;
    }
}
