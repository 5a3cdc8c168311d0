package particlelab.accuracy;

import java.util.ArrayList;
import java.util.List;
import particlelab.reference.CostMeter;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Scheme;
import particlelab.reference.Stepper;


/**
 * The work-precision sweep: for every canonical case and stepper, the final-position error
 * after {@link CanonicalCase#DURATION_SECONDS} at each step size, the cost of a step, and the
 * measured convergence order.
 */
final class WorkPrecisionStudy {

    /**
     * Errors at or below this (in metres) count as round-off and end an order fit: double
     * round-off of these runs (under 1e4 steps of values near 100 m) stays below it, and
     * {@link OrderFit} also stops where the error no longer falls with h.
     */
    static final double ROUND_OFF_FLOOR = 1e-11;
    /** The step size the cost of a step is timed at (in seconds). */
    static final double TIMING_STEP_SECONDS = 1.0 / 60.0;
    /**
     * Steps per timed call, each call from the launch: after 2000 steps at b/m = 2 /s, the
     * strongest drag timed, vx is still 7e-29 m/s, a normal float.
     */
    static final int STEPS_PER_TIMING_CALL = 2000;

    /** One run: a stepper on a case at one h. */
    static final class Point {
        final CanonicalCase scene;
        final Scheme scheme;
        final double stepSeconds;
        final int steps;
        final double errorMetres;
        /** The stepper's cost per step, min / median / max over the meter's rounds (ns). */
        final CostMeter.Spread nanosPerStepSpread;
        /** Its median (ns). */
        final double nanosPerStep;

        Point(CanonicalCase scene, Scheme scheme, double stepSeconds, int steps,
                double errorMetres, CostMeter.Spread nanosPerStep) {
            this.scene = scene;
            this.scheme = scheme;
            this.stepSeconds = stepSeconds;
            this.steps = steps;
            this.errorMetres = errorMetres;
            this.nanosPerStepSpread = nanosPerStep;
            this.nanosPerStep = nanosPerStep.median();
        }

        /** The cost of simulating one second at this h, the median (in ns). */
        double nanosPerSimulatedSecond() {
            return nanosPerStep / stepSeconds;
        }

        /** The cost of simulating one second at this h in the cheapest round (in ns). */
        double minNanosPerSimulatedSecond() {
            return nanosPerStepSpread.min() / stepSeconds;
        }

        /** The cost of simulating one second at this h in the dearest round (in ns). */
        double maxNanosPerSimulatedSecond() {
            return nanosPerStepSpread.max() / stepSeconds;
        }
    }

    /** A fitted order next to theory. */
    static final class Order {
        final CanonicalCase scene;
        final Scheme scheme;
        final double measured;
        final double theoretical;
        final double largestErrorMetres;

        Order(CanonicalCase scene, Scheme scheme, double measured, double theoretical,
                double largestErrorMetres) {
            this.scene = scene;
            this.scheme = scheme;
            this.measured = measured;
            this.theoretical = theoretical;
            this.largestErrorMetres = largestErrorMetres;
        }
    }

    final List<Point> points = new ArrayList<>();
    final List<Order> orders = new ArrayList<>();

    private WorkPrecisionStudy() {
    }

    /**
     * Count the units of work {@link #run} reports to the progress bar.
     *
     * @return cases × supported schemes
     */
    static int units() {
        int count = 0;
        for (CanonicalCase scene : CanonicalCase.all()) {
            for (Scheme scheme : Scheme.values()) {
                if (scheme.supports(scene.forces())) {
                    ++count;
                }
            }
        }
        return count;
    }

    static WorkPrecisionStudy run(ReportConfig config, CostMeter meter, ProgressBar progress) {
        WorkPrecisionStudy study = new WorkPrecisionStudy();
        double[] steps = config.steps();
        double smallestStep = steps[steps.length - 1];
        for (CanonicalCase scene : CanonicalCase.all()) {
            ForceModel forces = scene.forces();
            MotionState launch = CanonicalCase.launch();
            MotionState reference = ClosedForms.reference(forces, launch,
                    CanonicalCase.DURATION_SECONDS, new MotionState());
            for (Scheme scheme : Scheme.values()) {
                if (!scheme.supports(forces)) {
                    continue;
                }
                progress.phase("work-precision: " + scene.id() + ", " + scheme.id());
                Stepper stepper = scheme.create(forces);
                CostMeter.Spread nanosPerStep = timeStep(meter, stepper, launch);
                double[] runSteps = scheme == Scheme.SEMI_IMPLICIT_EULER
                        ? config.floatSteps() : steps;
                List<Double> fitSteps = new ArrayList<>();
                List<Double> fitErrors = new ArrayList<>();
                double largest = 0.0;
                for (double h : runSteps) {
                    int count = (int) Math.round(CanonicalCase.DURATION_SECONDS / h);
                    MotionState state = new MotionState().set(launch);
                    stepper.advance(state, h, count);
                    double error = state.positionDistance(reference);
                    study.points.add(new Point(scene, scheme, h, count, error, nanosPerStep));
                    if (h >= smallestStep) {
                        fitSteps.add(h);
                        fitErrors.add(error);
                        largest = Math.max(largest, error);
                    }
                }
                double theory = scheme.theoreticalOrder(forces);
                // a method exact for this case has no order to measure: only round-off
                double measured = Double.isInfinite(theory) ? Double.NaN
                        : OrderFit.slope(toArray(fitSteps), toArray(fitErrors), ROUND_OFF_FLOOR);
                study.orders.add(new Order(scene, scheme, measured, theory, largest));
                progress.advance();
            }
        }
        return study;
    }

    private static CostMeter.Spread timeStep(CostMeter meter, Stepper stepper,
            MotionState launch) {
        MotionState state = new MotionState();
        return meter.measure(units -> timingFlight(stepper, launch, state),
                STEPS_PER_TIMING_CALL).spread();
    }

    /**
     * Take one timed call's steps: relaunch, then {@link #STEPS_PER_TIMING_CALL} steps of
     * {@link #TIMING_STEP_SECONDS}, so no timed flight is long enough for its velocity to decay
     * into subnormal numbers.
     *
     * @param stepper the stepper to time (not null)
     * @param launch the launch state (not null, not modified)
     * @param state the state to fly (not null, modified)
     * @return state
     */
    static MotionState timingFlight(Stepper stepper, MotionState launch, MotionState state) {
        state.set(launch);
        stepper.advance(state, TIMING_STEP_SECONDS, STEPS_PER_TIMING_CALL);
        return state;
    }

    private static double[] toArray(List<Double> values) {
        double[] array = new double[values.size()];
        for (int i = 0; i < array.length; ++i) {
            array[i] = values.get(i);
        }
        return array;
    }
}
