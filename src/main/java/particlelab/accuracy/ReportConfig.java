package particlelab.accuracy;

import particlelab.reference.CostMeter;

/**
 * How large a report to make: which step sizes, how many drag rates, particle counts, and how
 * long each timing loop runs. Three sizes: full (a few minutes on 2 cores), quick (a minute or
 * more) and tiny (seconds, for tests and smoke checks).
 */
public final class ReportConfig {

    /** The report's sizes. */
    public enum Size {
        /** Every step size and drag rate; timings long enough to be steady. */
        FULL,
        /** A smaller sweep for a first look. */
        QUICK,
        /** The smallest sweep that still fills every file, for tests. */
        TINY
    }

    private final Size size;
    private final int stepHalvings;
    private final int floatExtraHalvings;
    private final double[] linearRates;
    private final int[] particleCounts;
    private final CostMeter.Budget budget;

    private ReportConfig(Size size, int stepHalvings, int floatExtraHalvings,
            double[] linearRates, int[] particleCounts, CostMeter.Budget budget) {
        this.size = size;
        this.stepHalvings = stepHalvings;
        this.floatExtraHalvings = floatExtraHalvings;
        this.linearRates = linearRates;
        this.particleCounts = particleCounts;
        this.budget = budget;
    }

    /**
     * Create the configuration of a size.
     *
     * @param size the size (not null)
     * @return a new configuration
     */
    public static ReportConfig of(Size size) {
        switch (size) {
            case FULL:
                return new ReportConfig(size, 7, 4,
                        new double[] {0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100},
                        new int[] {1_000, 10_000, 100_000, 1_000_000}, CostMeter.Budget.FULL);
            case QUICK:
                return new ReportConfig(size, 5, 2, new double[] {0.1, 1, 10, 100},
                        new int[] {1_000, 100_000}, CostMeter.Budget.QUICK);
            case TINY:
                return new ReportConfig(size, 3, 1, new double[] {1, 10},
                        new int[] {1_000}, CostMeter.Budget.TINY);
            default:
                throw new AssertionError(size);
        }
    }

    /**
     * Return the size.
     *
     * @return the size (not null)
     */
    public Size size() {
        return size;
    }

    /**
     * Return the step sizes for every stepper: 1/15 s halved {@code stepHalvings} times.
     *
     * @return new array, largest first (in seconds)
     */
    public double[] steps() {
        return halvings(stepHalvings);
    }

    /**
     * Return the step sizes for the float run of the shared integrator: those of
     * {@link #steps()} and a few smaller, to show where float round-off takes over.
     *
     * @return new array, largest first (in seconds)
     */
    public double[] floatSteps() {
        return halvings(stepHalvings + floatExtraHalvings);
    }

    /**
     * Return the damping rates b/m of the stability map.
     *
     * @return new array (in 1/s)
     */
    public double[] linearRates() {
        return linearRates.clone();
    }

    /**
     * Return the particle counts of the bulk benchmarks.
     *
     * @return new array
     */
    public int[] particleCounts() {
        return particleCounts.clone();
    }

    /**
     * Return how long each timing loop warms up before measuring.
     *
     * @return the time (in nanoseconds)
     */
    public long warmupNanos() {
        return budget.warmupNanos();
    }

    /**
     * Return how long each measured round lasts, at least.
     *
     * @return the time (in nanoseconds)
     */
    public long roundNanos() {
        return budget.roundNanos();
    }

    /**
     * Return how many rounds are measured; the median is reported.
     *
     * @return the count (&ge;1)
     */
    public int rounds() {
        return budget.rounds();
    }

    /**
     * Return the timing budget, for a {@link CostMeter}.
     *
     * @return the budget (not null)
     */
    public CostMeter.Budget budget() {
        return budget;
    }

    private static double[] halvings(int count) {
        double[] steps = new double[count + 1];
        for (int i = 0; i <= count; ++i) {
            steps[i] = 1.0 / (15 << i);
        }
        return steps;
    }
}
