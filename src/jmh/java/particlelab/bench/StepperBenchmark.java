package particlelab.bench;

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
import particlelab.reference.ExactDragStep;
import particlelab.reference.ForwardEuler;
import particlelab.accuracy.LectureStyleParticle;
import particlelab.reference.MidpointStepper;
import particlelab.reference.MotionState;
import particlelab.accuracy.OneParticleScene;
import particlelab.reference.RungeKutta4;
import particlelab.reference.SharedEulerStepper;
import particlelab.reference.VelocityVerlet;

/**
 * One particle under gravity and linear drag ({@link OneParticleScene}: b/m = 0.5/s,
 * h = 1/60 s): each invocation relaunches it and flies it
 * {@value OneParticleScene#STEPS_PER_LAUNCH} steps, with each stepper and with the two
 * references, the lecture's allocating style and the primitive loop. The relaunch keeps every
 * velocity far from the subnormal floats that a never-relaunched flight decays into. Scores are
 * per particle-step. Consecutive steps of one particle depend on each other, so these measure
 * latency.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Thread)
public class StepperBenchmark {

    private static final int STEPS = OneParticleScene.STEPS_PER_LAUNCH;

    private OneParticleScene scene;
    // concrete types, so each benchmark calls one known class
    private ForwardEuler forwardEuler;
    private SharedEulerStepper semiImplicitEuler;
    private VelocityVerlet velocityVerlet;
    private MidpointStepper midpoint;
    private RungeKutta4 rk4;
    private ExactDragStep exact;

    /** Build the scene and the steppers once per trial. */
    @Setup(Level.Trial)
    public void prepare() {
        scene = new OneParticleScene();
        forwardEuler = new ForwardEuler(scene.forces());
        semiImplicitEuler = new SharedEulerStepper(scene.forces());
        velocityVerlet = new VelocityVerlet(scene.forces());
        midpoint = new MidpointStepper(scene.forces());
        rk4 = new RungeKutta4(scene.forces());
        exact = new ExactDragStep(scene.forces());
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState forwardEuler() {
        return scene.fly(forwardEuler);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState semiImplicitEuler() {
        return scene.fly(semiImplicitEuler);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState velocityVerlet() {
        return scene.fly(velocityVerlet);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState midpoint() {
        return scene.fly(midpoint);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState rk4() {
        return scene.fly(rk4);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public MotionState exact() {
        return scene.fly(exact);
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public LectureStyleParticle lectureStyle() {
        return scene.flyLectureStyle();
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public float[] primitiveLoop() {
        return scene.flyPrimitiveLoop();
    }
}
