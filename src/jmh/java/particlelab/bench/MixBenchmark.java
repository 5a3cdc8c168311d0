package particlelab.bench;

import com.jme3.math.Vector3f;
import java.util.Arrays;
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
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;

/**
 * The shared integrator for every force mix of the demos ({@code gravity}, {@code linear}:
 * gravity + linear drag, {@code quadratic}: gravity + quadratic drag, {@code thrust-linear}:
 * gravity + linear drag + thrust), against a hand-written primitive float loop for the same mix
 * and against the lecture's allocating {@code Vector3f} style. Particles of 1 kg, h = 1/60 s.
 * Scores are per particle-step.
 *
 * <ul>
 * <li>{@code single*}: one particle, {@value #STEPS} dependent steps per invocation
 * (latency); {@code singleSharedWithRegime} adds the stability bookkeeping the demos do every
 * step ({@code regime}).</li>
 * <li>{@code objects*}: {@value #OBJECTS} particles as objects, one step each per invocation
 * (the demos' loop of {@code step(particle, h)}, and {@code step(Particle[], h)}).</li>
 * <li>{@code bulk*}: N particles packed in planar arrays: {@code stepPacked} against the
 * primitive loop, N per invocation.</li>
 * </ul>
 *
 * <p>Every state stays in the normal float range: the states are relaunched every
 * {@value #RELAUNCH_STEPS} steps, long before a velocity component decaying under drag
 * (factor 1 − h·b/m ≈ 0.9917 per step) could become subnormal (after about 10^4 steps), where
 * float arithmetic is 30–40 times slower.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class MixBenchmark {

    /** Dependent steps of one particle per invocation. */
    public static final int STEPS = 1000;
    /** Particles as objects in the {@code objects*} benchmarks. */
    public static final int OBJECTS = 1000;
    /** Steps after which every state is launched again (a multiple of {@link #STEPS}). */
    public static final int RELAUNCH_STEPS = 4000;

    private static final float H = 1f / 60f;
    private static final float G = Gravity.STANDARD_G;
    /** b (kg/s): b/m = 0.5/s. */
    private static final float LINEAR = 0.5f;
    /** c (kg/m): terminal speed sqrt(m·g/c) = 22 m/s. */
    private static final float QUADRATIC = 0.02f;
    /** k (N): with b, a cruise speed k/b = 8 m/s along the flight. */
    private static final float THRUST = 4f;
    private static final float MASS = 1f;

    /** A force mix: its forces, and the coefficients the hand-written loops use. */
    public enum Mix {
        GRAVITY(0f, 0f, 0f), LINEAR(MixBenchmark.LINEAR, 0f, 0f),
        QUADRATIC(0f, MixBenchmark.QUADRATIC, 0f),
        THRUST_LINEAR(MixBenchmark.LINEAR, 0f, MixBenchmark.THRUST);

        final float linear;
        final float quadratic;
        final float thrust;

        Mix(float linear, float quadratic, float thrust) {
            this.linear = linear;
            this.quadratic = quadratic;
            this.thrust = thrust;
        }

        /** The mix named as in benchmarks.csv: gravity, linear, quadratic, thrust-linear. */
        static Mix named(String name) {
            return valueOf(name.toUpperCase().replace('-', '_'));
        }

        ParticleIntegrator integrator() {
            switch (this) {
                case GRAVITY:
                    return new ParticleIntegrator(new Gravity());
                case LINEAR:
                    return new ParticleIntegrator(new Gravity(), new LinearDrag(linear));
                case QUADRATIC:
                    return new ParticleIntegrator(new Gravity(), new QuadraticDrag(quadratic));
                default:
                    return new ParticleIntegrator(new Force[] {new Gravity(),
                        new LinearDrag(linear), new Thrust(thrust)});
            }
        }

        boolean speedDependent() {
            return quadratic != 0f || thrust != 0f;
        }
    }

    /** One particle, held four ways. */
    @State(Scope.Thread)
    public static class Single {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;

        Mix forces;
        ParticleIntegrator integrator;
        Particle particle;
        LectureStyle lecture;
        final float[] position = new float[3];
        final float[] velocity = new float[3];
        int steps;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            forces = Mix.named(mix);
            integrator = forces.integrator();
            particle = new Particle();
            lecture = new LectureStyle();
            launch();
        }

        /** Count the steps about to be taken; relaunch when due. */
        void beforeSteps(int count) {
            steps += count;
            if (steps > RELAUNCH_STEPS) {
                launch();
                steps = count;
            }
        }

        private void launch() {
            particle.position.zero();
            particle.velocity.set(20f, 30f, 5f);
            lecture.position = new Vector3f();
            lecture.velocity = new Vector3f(20f, 30f, 5f);
            position[0] = 0f;
            position[1] = 0f;
            position[2] = 0f;
            velocity[0] = 20f;
            velocity[1] = 30f;
            velocity[2] = 5f;
        }
    }

    /** {@value #OBJECTS} particles as objects and as lecture-style objects. */
    @State(Scope.Thread)
    public static class ManyObjects {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;

        Mix forces;
        ParticleIntegrator integrator;
        Particle[] particles;
        LectureStyle[] lecture;
        int steps;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            forces = Mix.named(mix);
            integrator = forces.integrator();
            particles = new Particle[OBJECTS];
            lecture = new LectureStyle[OBJECTS];
            for (int i = 0; i < OBJECTS; ++i) {
                particles[i] = new Particle();
                lecture[i] = new LectureStyle();
            }
            launch();
        }

        /** Count one step; relaunch when due. */
        void beforeStep() {
            if (++steps > RELAUNCH_STEPS) {
                launch();
                steps = 1;
            }
        }

        private void launch() {
            for (int i = 0; i < OBJECTS; ++i) {
                particles[i].position.zero();
                particles[i].velocity.set(launchVelocity(i, 0), launchVelocity(i, 1),
                        launchVelocity(i, 2));
                lecture[i].position = new Vector3f();
                lecture[i].velocity = particles[i].velocity.clone();
            }
        }
    }

    /** N particles packed in planar arrays. */
    @State(Scope.Thread)
    public static class Bulk {
        /** The force mix. */
        @Param({"gravity", "linear", "quadratic", "thrust-linear"})
        public String mix;
        /** N. */
        @Param({"1000", "10000", "100000", "1000000"})
        public int particles;

        Mix forces;
        ParticleIntegrator integrator;
        float[] positions;
        float[] velocities;
        float[] launchVelocities;
        int steps;

        /** Build the scene. */
        @Setup(Level.Trial)
        public void build() {
            forces = Mix.named(mix);
            integrator = forces.integrator();
            positions = new float[3 * particles];
            velocities = new float[3 * particles];
            launchVelocities = new float[3 * particles];
            for (int i = 0; i < particles; ++i) {
                for (int axis = 0; axis < 3; ++axis) {
                    launchVelocities[axis * particles + i] = launchVelocity(i, axis);
                }
            }
            launch();
        }

        /** Count one step; relaunch when due. */
        void beforeStep() {
            if (++steps > RELAUNCH_STEPS) {
                launch();
                steps = 1;
            }
        }

        private void launch() {
            Arrays.fill(positions, 0f);
            System.arraycopy(launchVelocities, 0, velocities, 0, velocities.length);
        }
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singleLectureStyle(Single s) {
        s.beforeSteps(STEPS);
        for (int n = 0; n < STEPS; ++n) {
            s.lecture.step(s.forces);
        }
        return s.lecture;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singleSharedObjects(Single s) {
        s.beforeSteps(STEPS);
        for (int n = 0; n < STEPS; ++n) {
            s.integrator.step(s.particle, H);
        }
        return s.particle;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public int singleSharedWithRegime(Single s) {
        s.beforeSteps(STEPS);
        int worst = 0;
        for (int n = 0; n < STEPS; ++n) {
            worst = Math.max(worst, s.integrator.regime(s.particle, H).ordinal());
            s.integrator.step(s.particle, H);
        }
        return worst;
    }

    @Benchmark
    @OperationsPerInvocation(STEPS)
    public Object singlePrimitiveLoop(Single s) {
        s.beforeSteps(STEPS);
        PrimitiveMix.stepOne(s.position, s.velocity, s.forces, STEPS);
        return s.position;
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public Object objectsLectureStyle(ManyObjects s) {
        s.beforeStep();
        LectureStyle[] lecture = s.lecture;
        for (int i = 0; i < lecture.length; ++i) {
            lecture[i].step(s.forces);
        }
        return lecture;
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public Object objectsSharedObjects(ManyObjects s) {
        s.beforeStep();
        Particle[] particles = s.particles;
        for (int i = 0; i < particles.length; ++i) {
            s.integrator.step(particles[i], H);
        }
        return particles;
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public Object objectsSharedArray(ManyObjects s) {
        s.beforeStep();
        s.integrator.step(s.particles, H);
        return s.particles;
    }

    @Benchmark
    @OperationsPerInvocation(OBJECTS)
    public int objectsSharedWithRegime(ManyObjects s) {
        s.beforeStep();
        Particle[] particles = s.particles;
        int worst = 0;
        for (int i = 0; i < particles.length; ++i) {
            worst = Math.max(worst, s.integrator.regime(particles[i], H).ordinal());
            s.integrator.step(particles[i], H);
        }
        return worst;
    }

    @Benchmark
    public Object bulkSharedBatch(Bulk s) {
        s.beforeStep();
        s.integrator.stepPacked(s.positions, s.velocities, s.particles, MASS, H);
        return s.positions;
    }

    @Benchmark
    public Object bulkPrimitiveLoop(Bulk s) {
        s.beforeStep();
        PrimitiveMix.step(s.positions, s.velocities, s.particles, s.forces);
        return s.positions;
    }

    /** The launch velocity of particle i along an axis: slightly different for each. */
    static float launchVelocity(int i, int axis) {
        switch (axis) {
            case 0:
                return 20f + i % 7;
            case 1:
                return 30f + i % 11;
            default:
                return i % 5 - 2f;
        }
    }

    /**
     * The lecture slides' style for every mix: new vectors from jME's allocating
     * {@code mult}/{@code add}/{@code divide} every step, replacing the particle's.
     */
    static final class LectureStyle {
        Vector3f position = new Vector3f();
        Vector3f velocity = new Vector3f();
        final Vector3f gravity = new Vector3f(0f, -G, 0f);

        void step(Mix mix) {
            Vector3f force = new Vector3f();
            if (mix.linear != 0f) {
                force = force.add(velocity.mult(-mix.linear));
            }
            if (mix.quadratic != 0f) {
                force = force.add(velocity.mult(-mix.quadratic * velocity.length()));
            }
            if (mix.thrust != 0f && velocity.length() >= Thrust.MIN_SPEED) {
                force = force.add(velocity.normalize().mult(mix.thrust));
            }
            Vector3f acceleration = gravity.add(force.divide(MASS));
            velocity = velocity.add(acceleration.mult(H));
            position = position.add(velocity.mult(H));
        }
    }

    /**
     * The practical speed limit for each mix: the semi-implicit Euler step written by hand
     * over primitive floats, no objects, no checks, the coefficients folded by hand:
     * {@code V ← (1 − h·σ)·V + h·g} with {@code σ = (b + c·|V| − k/|V|)/m}.
     */
    static final class PrimitiveMix {

        private PrimitiveMix() {
        }

        /** Several steps of one particle in two 3-float arrays. */
        static void stepOne(float[] position, float[] velocity, Mix mix, int steps) {
            float hb = H * mix.linear / MASS;
            float hc = H * mix.quadratic / MASS;
            float hk = H * mix.thrust / MASS;
            float hg = -H * G;
            float px = position[0];
            float py = position[1];
            float pz = position[2];
            float vx = velocity[0];
            float vy = velocity[1];
            float vz = velocity[2];
            if (mix.speedDependent()) {
                for (int n = 0; n < steps; ++n) {
                    float speed = (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
                    float thrust = speed >= Thrust.MIN_SPEED ? hk / speed : 0f;
                    float factor = 1f - hb - hc * speed + thrust;
                    vx *= factor;
                    vy = vy * factor + hg;
                    vz *= factor;
                    px += H * vx;
                    py += H * vy;
                    pz += H * vz;
                }
            } else {
                float factor = 1f - hb;
                for (int n = 0; n < steps; ++n) {
                    vx *= factor;
                    vy = vy * factor + hg;
                    vz *= factor;
                    px += H * vx;
                    py += H * vy;
                    pz += H * vz;
                }
            }
            position[0] = px;
            position[1] = py;
            position[2] = pz;
            velocity[0] = vx;
            velocity[1] = vy;
            velocity[2] = vz;
        }

        /** One step of N particles in planar arrays. */
        static void step(float[] positions, float[] velocities, int count, Mix mix) {
            float hb = H * mix.linear / MASS;
            float hg = -H * G;
            if (!mix.speedDependent()) {
                float factor = 1f - hb;
                for (int axis = 0; axis < 3; ++axis) {
                    float stepGravity = axis == 1 ? hg : 0f;
                    int end = (axis + 1) * count;
                    for (int i = axis * count; i < end; ++i) {
                        float v = velocities[i] * factor + stepGravity;
                        velocities[i] = v;
                        positions[i] += H * v;
                    }
                }
                return;
            }
            float hc = H * mix.quadratic / MASS;
            float hk = H * mix.thrust / MASS;
            for (int x = 0, y = count, z = 2 * count; x < count; ++x, ++y, ++z) {
                float vx = velocities[x];
                float vy = velocities[y];
                float vz = velocities[z];
                float speed = (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
                float thrust = speed >= Thrust.MIN_SPEED ? hk / speed : 0f;
                float factor = 1f - hb - hc * speed + thrust;
                vx *= factor;
                vy = vy * factor + hg;
                vz *= factor;
                velocities[x] = vx;
                velocities[y] = vy;
                velocities[z] = vz;
                positions[x] += H * vx;
                positions[y] += H * vy;
                positions[z] += H * vz;
            }
        }
    }
}
