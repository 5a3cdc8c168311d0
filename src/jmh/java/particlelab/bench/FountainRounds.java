package particlelab.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import particlelab.accuracy.AaControl;
import particlelab.accuracy.HostInfo;
import particlelab.lecture.FountainPoints;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleBatch;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.PointCloudMesh;
import particlelab.world.Fountain;

/**
 * The fountain's frame, part by part, timed side by side in one JVM by the thread's CPU time
 * in rotating rounds (each round starts at another row, so a slow spell of the machine falls
 * on a different row each time), min / median / max over the rounds:
 * <ul>
 * <li>{@code fountain-step/N}: {@link Fountain#step} in full flow ({@value #FLOW_STEPS} steps
 * first, about 89 % of the pool in flight);</li>
 * <li>{@code step-packed/N}: {@link ParticleBatch#stepPacked} of all N particles of a
 * copy of that state under the same forces, restarted from the copy every
 * {@value #STEPS_PER_COPY} steps (as {@code FountainBenchmark} does);</li>
 * <li>{@code step-packed-again/N}: the same on a second copy with an integrator of its own,
 * the A/A pass: how far identical work appears to differ in these rounds;</li>
 * <li>{@code mesh-update/N}: {@link FountainPoints#update} of a fountain in full flow into a
 * {@link PointCloudMesh} built without a window;</li>
 * <li>{@code plain-copy/N}: the same bytes copied from arrays into direct buffers of the same
 * layout (the mesh's planar layout: three {@code FloatBuffer.put} of the positions, one an
 * axis, and one {@code IntBuffer.put} of the colours), as many points as the update
 * writes;</li>
 * <li>{@code mesh-per-point/N}: the update as it was before issue 23 (every slot, one absolute
 * put per float and per colour byte, the colour scaled per point), for the record.</li>
 * </ul>
 * Then the host ({@link HostInfo}) and the ratios per round: fountain ÷ stepPacked with its
 * A/A pass (stepPacked again ÷ stepPacked) and the verdict on "within 2×" by the A/A rule
 * (judged only where the median lies outside the A/A band and 2× lies outside the band
 * around the median, {@link AaControl}), mesh update ÷ plain copy, and the fountain's step as
 * a share of a 16.7 ms frame.
 *
 * <p>Usage: {@code FountainRounds [ROUNDS [MILLIS [N,N,... [steps]]]]}; defaults 7 rounds of
 * 300 ms per row, N = 10000,100000,1000000; {@code steps} times the three step rows alone.
 */
public final class FountainRounds {

    /** Steps before timing: the fountain fills its pool. */
    static final int FLOW_STEPS = 900;
    /** The bare step's state is restored from the copy this often. */
    static final int STEPS_PER_COPY = 600;
    private static final float STEP_SECONDS = 1f / 60f;
    private static final double FRAME_MILLIS = 1000.0 / 60.0;
    private static final float WATER_BRIGHTNESS = 0.15f;
    /** The rows each pool size has, in the order {@link #addRows} adds them. */
    private static final int ROWS_PER_COUNT = 6;
    /** The fountain's whole step should take at most this many times {@code stepPacked}. */
    private static final double FOUNTAIN_TARGET = 2.0;
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    /** Keeps the results alive so no work is dead code. */
    private static volatile Object sink;

    private FountainRounds() {
    }

    /**
     * Time the rows.
     *
     * @param args rounds, milliseconds per row and round, the pool sizes
     */
    public static void main(String[] args) {
        HostInfo host = HostInfo.now();
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 7;
        long budget = (args.length > 1 ? Long.parseLong(args[1]) : 300L) * 1_000_000L;
        int[] counts = args.length > 2 ? Arrays.stream(args[2].split(","))
                .mapToInt(Integer::parseInt).toArray() : new int[] {10_000, 100_000, 1_000_000};
        boolean stepsOnly = args.length > 3 && args[3].equals("steps");
        List<String> names = new ArrayList<>();
        List<Runnable> rows = new ArrayList<>();
        for (int n : counts) {
            addRows(n, names, rows);
        }
        if (stepsOnly) {
            for (int r = rows.size() - 1; r >= 0; --r) {
                if (r % ROWS_PER_COUNT > 2) {
                    rows.set(r, null);
                }
            }
        }
        int size = rows.size();
        double[][] millis = new double[size][rounds];
        for (Runnable row : rows) {
            if (row != null) {
                time(row, 2 * budget);
            }
        }
        for (int round = 0; round < rounds; ++round) {
            for (int k = 0; k < size; ++k) {
                int r = (round + k) % size;
                millis[r][round] = rows.get(r) == null ? Double.NaN
                        : time(rows.get(r), budget) / 1e6;
            }
        }
        System.out.printf(Locale.ROOT, "Host:%n%s%n%d rounds of %d ms per row, thread CPU time,"
                + " load average %.2f at the end%n%n| row | ms per call: min / median / max |"
                + " ns per particle of the pool (median) |%n|---|---|---|%n", host.block(),
                rounds, budget / 1_000_000L, ManagementFactory.getOperatingSystemMXBean()
                        .getSystemLoadAverage());
        for (int r = 0; r < size; ++r) {
            if (rows.get(r) == null) {
                continue;
            }
            double[] sorted = millis[r].clone();
            Arrays.sort(sorted);
            int n = Integer.parseInt(names.get(r).substring(names.get(r).indexOf('/') + 1));
            System.out.printf(Locale.ROOT, "| `%s` | %.4f / **%.4f** / %.4f | %.3f |%n",
                    names.get(r), sorted[0], median(sorted), sorted[rounds - 1],
                    median(sorted) * 1e6 / n);
        }
        System.out.printf("%n| ratio per round | min / median / max |%n|---|---|%n");
        StringBuilder verdicts = new StringBuilder();
        for (int c = 0; c < counts.length; ++c) {
            int at = c * ROWS_PER_COUNT;
            double[] fountain = printRatio("fountain ÷ stepPacked/" + counts[c], millis[at],
                    millis[at + 1], 1.0);
            double[] aa = printRatio("A/A: stepPacked again ÷ stepPacked/" + counts[c],
                    millis[at + 2], millis[at + 1], 1.0);
            verdicts.append(String.format(Locale.ROOT, "fountain ÷ stepPacked ≤ %.0f×, N = %d:"
                    + " %s%n", FOUNTAIN_TARGET, counts[c], verdict(fountain, aa)));
            printRatio("fountain ÷ 16.7 ms frame/" + counts[c], millis[at], null,
                    FRAME_MILLIS);
            if (stepsOnly) {
                continue;
            }
            printRatio("mesh update ÷ plain copy/" + counts[c], millis[at + 3], millis[at + 4],
                    1.0);
            printRatio("mesh per point (before) ÷ plain copy/" + counts[c], millis[at + 5],
                    millis[at + 4], 1.0);
        }
        System.out.printf("%n%s", verdicts);
    }

    /**
     * The verdict on the fountain's target by the A/A rule: none where the median lies inside
     * the A/A band (identical work differed as much) or where the target lies inside the band
     * around the median (a run as noisy as its A/A pass could read either side of it).
     */
    private static String verdict(double[] ratio, double[] aa) {
        double aaMin = Arrays.stream(aa).min().getAsDouble();
        double aaMax = Arrays.stream(aa).max().getAsDouble();
        double median = AaControl.median(ratio);
        String band = String.format(Locale.ROOT, "median %.3f×, A/A band %.3f–%.3f", median,
                AaControl.bandLow(aaMin, aaMax), AaControl.bandHigh(aaMin, aaMax));
        if (AaControl.isInsideBand(aaMin, aaMax, median)) {
            return "inside the A/A band: no verdict (" + band + ")";
        }
        if (AaControl.isInsideBand(aaMin, aaMax, median / FOUNTAIN_TARGET)) {
            return "target within the A/A band: no verdict (" + band + ")";
        }
        return (median <= FOUNTAIN_TARGET ? "met" : "missed") + " (" + band + ")";
    }

    private static void addRows(int n, List<String> names, List<Runnable> rows) {
        Fountain stepped = flowing(n);
        names.add("fountain-step/" + n);
        rows.add(() -> {
            stepped.step(STEP_SECONDS);
            sink = stepped;
        });

        Fountain start = flowing(n);
        float[] startPositions = start.getPositions().clone();
        float[] startVelocities = start.getVelocities().clone();
        float[] positions = startPositions.clone();
        float[] velocities = startVelocities.clone();
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(Fountain.DRAG_B));
        int[] steps = {0};
        names.add("step-packed/" + n);
        rows.add(() -> {
            if (++steps[0] == STEPS_PER_COPY) {
                steps[0] = 0;
                System.arraycopy(startPositions, 0, positions, 0, positions.length);
                System.arraycopy(startVelocities, 0, velocities, 0, velocities.length);
            }
            integrator.batch().stepPacked(positions, velocities, n, Fountain.MASS_KG, STEP_SECONDS);
            sink = positions;
        });

        float[] positionsAgain = startPositions.clone();
        float[] velocitiesAgain = startVelocities.clone();
        ParticleIntegrator integratorAgain = new ParticleIntegrator(new Gravity(),
                new LinearDrag(Fountain.DRAG_B));
        int[] stepsAgain = {0};
        names.add("step-packed-again/" + n);
        rows.add(() -> {
            if (++stepsAgain[0] == STEPS_PER_COPY) {
                stepsAgain[0] = 0;
                System.arraycopy(startPositions, 0, positionsAgain, 0, positionsAgain.length);
                System.arraycopy(startVelocities, 0, velocitiesAgain, 0,
                        velocitiesAgain.length);
            }
            integratorAgain.batch().stepPacked(positionsAgain, velocitiesAgain, n,
                    Fountain.MASS_KG, STEP_SECONDS);
            sink = positionsAgain;
        });

        PointCloudMesh mesh = new PointCloudMesh(n, Fountain.REGION_TOP);
        FountainPoints update = new FountainPoints(mesh, WATER_BRIGHTNESS);
        update.update(start);
        update.update(start);
        names.add("mesh-update/" + n);
        rows.add(() -> {
            update.update(start);
            sink = mesh;
        });

        int points = update.countLastWritten();
        float[] sourcePositions = new float[3 * n];
        FloatBuffer[] copyPositions = new FloatBuffer[3];
        for (int axis = 0; axis < 3; ++axis) {
            mesh.getPositionData(axis).get(0, sourcePositions, axis * n, n);
            copyPositions[axis] = ByteBuffer.allocateDirect(4 * n)
                    .order(ByteOrder.nativeOrder()).asFloatBuffer();
        }
        int[] sourceColours = new int[n];
        mesh.getColourData().duplicate().order(ByteOrder.LITTLE_ENDIAN).asIntBuffer()
                .get(0, sourceColours, 0, n);
        IntBuffer copyColours = ByteBuffer.allocateDirect(4 * n)
                .order(ByteOrder.LITTLE_ENDIAN).asIntBuffer();
        names.add("plain-copy/" + n);
        rows.add(() -> {
            copyPositions[0].put(0, sourcePositions, 0, points);
            copyPositions[1].put(0, sourcePositions, n, points);
            copyPositions[2].put(0, sourcePositions, 2 * n, points);
            copyColours.put(0, sourceColours, 0, points);
            sink = copyColours;
        });

        FloatBuffer oldPositions = ByteBuffer.allocateDirect(12 * n)
                .order(ByteOrder.nativeOrder()).asFloatBuffer();
        ByteBuffer oldColours = ByteBuffer.allocateDirect(4 * n).order(ByteOrder.nativeOrder());
        names.add("mesh-per-point/" + n);
        rows.add(() -> {
            perPoint(start, oldPositions, oldColours);
            sink = oldColours;
        });
    }

    /** The mesh update before issue 23: every slot, one put per float and per byte. */
    private static void perPoint(Fountain fountain, FloatBuffer positions, ByteBuffer colours) {
        float[] planar = fountain.getPositions();
        int n = fountain.getCapacity();
        for (int i = 0, at = 0; i < n; ++i, at += 3) {
            positions.put(at, planar[i]);
            positions.put(at + 1, planar[n + i]);
            positions.put(at + 2, planar[2 * n + i]);
        }
        for (int i = 0; i < n; ++i) {
            byte kind = fountain.getKind(i);
            float brightness = kind == Fountain.DORMANT ? 0f : kind == Fountain.WATER
                    ? WATER_BRIGHTNESS : kind == Fountain.SHELL ? 1f : fountain.fuseFraction(i);
            int rgb = fountain.getColour(i);
            int at = 4 * i;
            colours.put(at, (byte) Math.round(((rgb >> 16) & 0xff) * brightness));
            colours.put(at + 1, (byte) Math.round(((rgb >> 8) & 0xff) * brightness));
            colours.put(at + 2, (byte) Math.round((rgb & 0xff) * brightness));
            colours.put(at + 3, (byte) 0xff);
        }
    }

    private static Fountain flowing(int n) {
        Fountain fountain = new Fountain(n);
        for (int i = 0; i < FLOW_STEPS; ++i) {
            fountain.step(STEP_SECONDS);
        }
        return fountain;
    }

    /** Print a ratio's spread over the rounds; return the ratio per round. */
    private static double[] printRatio(String name, double[] over, double[] under,
            double unit) {
        int rounds = over.length;
        double[] ratio = new double[rounds];
        for (int i = 0; i < rounds; ++i) {
            ratio[i] = over[i] / (under == null ? unit : under[i]);
        }
        double[] sorted = ratio.clone();
        Arrays.sort(sorted);
        System.out.printf(Locale.ROOT, "| %s | %.3f / **%.3f** / %.3f |%n", name, sorted[0],
                median(sorted), sorted[rounds - 1]);
        return ratio;
    }

    /** The CPU time of one call, over calls that fill the budget (ns). */
    private static double time(Runnable workload, long budgetNanos) {
        long start = THREADS.getCurrentThreadCpuTime();
        long calls = 0;
        long now;
        do {
            workload.run();
            ++calls;
            now = THREADS.getCurrentThreadCpuTime();
        } while (now - start < budgetNanos);
        return (double) (now - start) / calls;
    }

    private static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
}
