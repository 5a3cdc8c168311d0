package particlelab.bench;

import com.jme3.math.Vector3f;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;
import particlelab.accuracy.AaControl;
import particlelab.accuracy.ForceMix;
import particlelab.accuracy.HostInfo;
import particlelab.accuracy.OneParticleMixScene;
import particlelab.physics.Particle;

/**
 * Where one particle's step goes: the shared {@code step(Particle, h)} (the demos' call)
 * against the one-particle primitive loop, and between them three hand-written loops that
 * take the integrator's parts away one at a time, so each difference is one cause:
 * <ul>
 * <li>{@code recipe-fields}: the recipe's arithmetic ({@code a = g − σ·V}, {@code V ← V + h·a},
 * {@code P ← P + h·V}, the product skipped where σ = 0 as the integrator does) on a
 * {@link Particle}'s {@code Vector3f} fields, with no validation, no staleness flag, no
 * remembered h and m and no finiteness check: shared ÷ this is what the integrator's own
 * code costs;</li>
 * <li>{@code recipe-registers}: the same arithmetic on locals: recipe-fields ÷ this is what
 * keeping the state in the particle's fields costs (each step's V is stored and read back);
 * </li>
 * <li>{@code fold-fields}: the primitive loop's arithmetic ({@code V·(1 − h·σ) + h·g}, two
 * dependent operations on V where the recipe has four, or one for gravity) on the fields;</li>
 * <li>{@code primitive-again}: the primitive loop of a second scene, the A/A pass: how far
 * identical work appears to differ in these rounds.</li>
 * </ul>
 * After the table, per mix: shared ÷ primitive with the verdict on "within 2×" by the A/A
 * rule ({@link AaControl}: judged only where the median lies outside the A/A band and 2× lies
 * outside the band around the median), and shared ÷ {@code recipe-registers}, the ratio to a
 * primitive loop computing the recipe's own floats (the overhead apart from the arithmetic).
 * Each flight is {@link OneParticleMixScene}'s: relaunch at (20, 30, 4) m/s, then
 * {@value OneParticleMixScene#STEPS_PER_LAUNCH} dependent steps of 1/60 s at 1 kg. The recipe
 * forms give the shared step's floats bit for bit (checked before timing; a mismatch stops
 * the run). Timed by the thread's CPU time in rotating rounds (each round starts at another
 * path), min / median / max of ns per step and of each path ÷ primitive within a round.
 *
 * <p>Usage: {@code OneParticleFloor [ROUNDS [MILLIS [MIX,...]]]}; defaults 9 rounds of 200 ms
 * per path, mixes {@code gravity,linear}.
 */
public final class OneParticleFloor {

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final String[] PATHS = {"primitive-loop", "shared-objects", "recipe-fields",
        "recipe-registers", "fold-fields", "primitive-again"};
    private static final int PRIMITIVE = 0;
    private static final int SHARED = 1;
    private static final int RECIPE_FIELDS = 2;
    private static final int RECIPE_REGISTERS = 3;
    private static final int FOLD_FIELDS = 4;
    /** The one-particle target: shared at most this many times the primitive loop. */
    private static final double TARGET = 2.0;
    private static final float STEP_SECONDS = 1f / 60f;
    private static final int STEPS = OneParticleMixScene.STEPS_PER_LAUNCH;
    /** Keeps the results alive so no work is dead code. */
    private static volatile Object sink;

    private final OneParticleMixScene scene;
    /** A second scene, for the A/A pass. */
    private final OneParticleMixScene sceneAgain;
    private final Particle particle = new Particle();
    private final float[] registers = new float[6];
    /** g per axis (m/s²), as the integrator's acceleration at rest gives it. */
    private final float gravityX;
    private final float gravityY;
    private final float gravityZ;
    /** σ = b/m (1/s). */
    private final float sigma;

    private OneParticleFloor(ForceMix mix) {
        scene = new OneParticleMixScene(mix);
        sceneAgain = new OneParticleMixScene(mix);
        Vector3f g = mix.integrator().acceleration(new Particle(), new Vector3f());
        gravityX = g.x;
        gravityY = g.y;
        gravityZ = g.z;
        sigma = mix.linearDrag() / ForceMix.MASS_KG;
        if (mix.quadraticDrag() != 0f || mix.thrustNewtons() != 0f) {
            throw new IllegalArgumentException("gravity and linear drag only, not " + mix.id());
        }
    }

    /**
     * Time every path for each mix.
     *
     * @param args rounds, milliseconds per path and round, mixes (comma-separated)
     */
    public static void main(String[] args) {
        HostInfo host = HostInfo.now();
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 9;
        long budget = (args.length > 1 ? Long.parseLong(args[1]) : 200L) * 1_000_000L;
        String[] mixes = (args.length > 2 ? args[2] : "gravity,linear").split(",");
        StringBuilder table = new StringBuilder();
        StringBuilder verdicts = new StringBuilder();
        table.append("| mix | path | ns per step: min / median / max "
                + "| ÷ primitive per round: min / median / max |\n|---|---|---|---|\n");
        for (String mixName : mixes) {
            OneParticleFloor floor = new OneParticleFloor(ForceMix.named(mixName));
            floor.checkSameFloats();
            for (int path = 0; path < PATHS.length; ++path) {
                floor.time(path, 3 * budget);
            }
            double[][] nanos = new double[PATHS.length][rounds];
            for (int round = 0; round < rounds; ++round) {
                for (int k = 0; k < PATHS.length; ++k) {
                    int path = (round + k) % PATHS.length;
                    nanos[path][round] = floor.time(path, budget) / STEPS;
                }
            }
            for (int path = 0; path < PATHS.length; ++path) {
                double[] ratio = new double[rounds];
                for (int round = 0; round < rounds; ++round) {
                    ratio[round] = nanos[path][round] / nanos[PRIMITIVE][round];
                }
                table.append(String.format(Locale.ROOT, "| %s | `%s` | %s | %s |%n", mixName,
                        PATHS[path], spread(nanos[path]), spread(ratio)));
            }
            verdicts.append(verdicts(mixName, nanos));
        }
        System.out.printf(Locale.ROOT, "Host:%n%s%n%d rounds of %d ms per path%n%n%s%n%s",
                host.block(), rounds, budget / 1_000_000L, table, verdicts);
    }

    /**
     * One mix's verdict on shared ≤ 2× primitive by the A/A rule, and shared ÷
     * recipe-registers.
     */
    private static String verdicts(String mixName, double[][] nanos) {
        int rounds = nanos[PRIMITIVE].length;
        double[] shared = new double[rounds];
        double[] aa = new double[rounds];
        double[] overRecipe = new double[rounds];
        for (int round = 0; round < rounds; ++round) {
            shared[round] = nanos[SHARED][round] / nanos[PRIMITIVE][round];
            aa[round] = nanos[PATHS.length - 1][round] / nanos[PRIMITIVE][round];
            overRecipe[round] = nanos[SHARED][round] / nanos[RECIPE_REGISTERS][round];
        }
        double aaMin = Arrays.stream(aa).min().getAsDouble();
        double aaMax = Arrays.stream(aa).max().getAsDouble();
        double median = AaControl.median(shared);
        String verdict = AaControl.isInsideBand(aaMin, aaMax, median)
                ? "inside the A/A band: no verdict"
                : AaControl.isInsideBand(aaMin, aaMax, median / TARGET)
                ? "target within the A/A band: no verdict"
                : median <= TARGET ? "met" : "missed";
        return String.format(Locale.ROOT, "%s: shared ÷ primitive %s, A/A (primitive again ÷"
                + " primitive) %s, band %.3f–%.3f: ≤ %.0f× %s; shared ÷ recipe-registers %s%n",
                mixName, spread(shared), spread(aa), AaControl.bandLow(aaMin, aaMax),
                AaControl.bandHigh(aaMin, aaMax), TARGET, verdict, spread(overRecipe));
    }

    /** Stop unless the recipe forms give the shared step's floats after a flight. */
    private void checkSameFloats() {
        Particle shared = scene.flySharedObjects();
        float[] viaFields = state(flyRecipeFields());
        float[] viaRegisters = flyRecipeRegisters().clone();
        float[] expected = state(shared);
        if (!Arrays.equals(expected, viaFields) || !Arrays.equals(expected, viaRegisters)) {
            throw new IllegalStateException("the recipe forms differ from step(Particle, h): "
                    + Arrays.toString(expected) + " / " + Arrays.toString(viaFields) + " / "
                    + Arrays.toString(viaRegisters));
        }
    }

    private static float[] state(Particle p) {
        return new float[] {p.position.x, p.position.y, p.position.z, p.velocity.x,
            p.velocity.y, p.velocity.z};
    }

    private Object fly(int path) {
        switch (path) {
            case PRIMITIVE:
                return scene.flyPrimitiveLoop();
            case SHARED:
                return scene.flySharedObjects();
            case RECIPE_FIELDS:
                return flyRecipeFields();
            case RECIPE_REGISTERS:
                return flyRecipeRegisters();
            case FOLD_FIELDS:
                return flyFoldFields();
            default:
                return sceneAgain.flyPrimitiveLoop();
        }
    }

    private Particle flyRecipeFields() {
        Vector3f position = particle.position;
        Vector3f velocity = particle.velocity;
        position.set(0f, 0f, 0f);
        velocity.set(20f, 30f, 4f);
        float h = STEP_SECONDS;
        float s = sigma;
        float gx = gravityX;
        float gy = gravityY;
        float gz = gravityZ;
        for (int n = 0; n < STEPS; ++n) {
            float vx = velocity.x;
            float vy = velocity.y;
            float vz = velocity.z;
            float ax = gx;
            float ay = gy;
            float az = gz;
            if (s != 0f) {
                ax -= s * vx;
                ay -= s * vy;
                az -= s * vz;
            }
            vx = vx + h * ax;
            vy = vy + h * ay;
            vz = vz + h * az;
            velocity.set(vx, vy, vz);
            position.set(position.x + h * vx, position.y + h * vy, position.z + h * vz);
        }
        return particle;
    }

    private float[] flyRecipeRegisters() {
        float h = STEP_SECONDS;
        float s = sigma;
        float gx = gravityX;
        float gy = gravityY;
        float gz = gravityZ;
        float px = 0f;
        float py = 0f;
        float pz = 0f;
        float vx = 20f;
        float vy = 30f;
        float vz = 4f;
        for (int n = 0; n < STEPS; ++n) {
            float ax = gx;
            float ay = gy;
            float az = gz;
            if (s != 0f) {
                ax -= s * vx;
                ay -= s * vy;
                az -= s * vz;
            }
            vx = vx + h * ax;
            vy = vy + h * ay;
            vz = vz + h * az;
            px += h * vx;
            py += h * vy;
            pz += h * vz;
        }
        float[] out = registers;
        out[0] = px;
        out[1] = py;
        out[2] = pz;
        out[3] = vx;
        out[4] = vy;
        out[5] = vz;
        return out;
    }

    private Particle flyFoldFields() {
        Vector3f position = particle.position;
        Vector3f velocity = particle.velocity;
        position.set(0f, 0f, 0f);
        velocity.set(20f, 30f, 4f);
        float h = STEP_SECONDS;
        float factor = 1f - h * sigma;
        float stepGravityX = h * gravityX;
        float stepGravityY = h * gravityY;
        float stepGravityZ = h * gravityZ;
        for (int n = 0; n < STEPS; ++n) {
            float vx = velocity.x * factor + stepGravityX;
            float vy = velocity.y * factor + stepGravityY;
            float vz = velocity.z * factor + stepGravityZ;
            velocity.set(vx, vy, vz);
            position.set(position.x + h * vx, position.y + h * vy, position.z + h * vz);
        }
        return particle;
    }

    /** The CPU time of one flight, over flights that fill the budget (ns). */
    private double time(int path, long budgetNanos) {
        long start = THREADS.getCurrentThreadCpuTime();
        long calls = 0;
        long now;
        do {
            for (int i = 0; i < 16; ++i) {
                sink = fly(path);
            }
            calls += 16;
            now = THREADS.getCurrentThreadCpuTime();
        } while (now - start < budgetNanos);
        return (double) (now - start) / calls;
    }

    private static String spread(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        double median = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        return String.format(Locale.ROOT, "%.3f / **%.3f** / %.3f", sorted[0], median,
                sorted[n - 1]);
    }
}
