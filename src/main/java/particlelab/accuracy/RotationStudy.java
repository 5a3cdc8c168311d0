package particlelab.accuracy;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import particlelab.reference.CostMeter;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationCheck;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;
import particlelab.rigid.RotationIntegrator;
import particlelab.rigid.SpinAngle;


/**
 * The rotation section's measurements: for a sphere spinning at constant ω, each orientation
 * method's angle error against the exact rotation and its orthogonality error {@code ‖RᵀR − I‖}
 * after {@link #ORIENTATION_SECONDS} at every step of the full sweep, with its cost per step;
 * and for the tennis racket (moments 1, 2, 3 spun near the middle axis) each angular method's
 * relative energy and |L| drift after {@link #RACKET_SECONDS}.
 */
final class RotationStudy {

    /** Simulated time of the orientation part (in seconds). */
    static final double ORIENTATION_SECONDS = 1.0;
    /** Simulated time of the racket part (in seconds): a few flips (one every 2.95 s). */
    static final double RACKET_SECONDS = 10.0;
    /** The orientation part's ω: 2π rad/s about (1, 1, 1)/√3, off every body axis. */
    static final Vector3f OMEGA = new Vector3f(1f, 1f, 1f)
            .multLocal((float) (2.0 * Math.PI / Math.sqrt(3.0)));
    /** The racket's moments (in kg·m²). */
    static final Inertia RACKET = Inertia.of(1f, 2f, 3f);
    /** The racket's start ω (body frame = world frame at t = 0, in rad/s): near the y axis. */
    static final Vector3f RACKET_OMEGA = new Vector3f(0.2f, 5f, 0.2f);
    /** The step the cost is timed at (in seconds): the demos' 1/60 s. */
    static final float COST_STEP_SECONDS = 1f / 60f;
    /** Timed steps between restarts of the cost body (R back to I; plain Euler grows). */
    static final int COST_RESTART_STEPS = 60;
    /** Timing passes, alternating the methods; each keeps its fastest. */
    static final int COST_PASSES = 3;

    /** One orientation method at one step size. */
    static final class OrientationError {
        final Orientation method;
        final double stepSeconds;
        final int steps;
        /** The angle to the exact rotation (rad, 0 to π: a distance, which wraps). */
        final double angleError;
        final double orthogonalityError;
        /**
         * The unwrapped lag, {@code |ω|·t} minus the angle turned about ω (rad, see
         * {@link SpinAngle}): equal to the angle error for a method that turns about ω, as
         * long as the lag stays below π, which the tests check over the whole sweep.
         */
        final double angleLag;

        OrientationError(Orientation method, double stepSeconds, int steps, double angleError,
                double orthogonalityError, double angleLag) {
            this.method = method;
            this.stepSeconds = stepSeconds;
            this.steps = steps;
            this.angleError = angleError;
            this.orthogonalityError = orthogonalityError;
            this.angleLag = angleLag;
        }
    }

    /** One angular method's racket drift at one step size. */
    static final class Drift {
        final Angular method;
        final double stepSeconds;
        final int steps;
        /** (E(T) − E(0))/E(0). */
        final double energyDrift;
        /** (|L|(T) − |L|(0))/|L|(0). */
        final double momentumDrift;

        Drift(Angular method, double stepSeconds, int steps, double energyDrift,
                double momentumDrift) {
            this.method = method;
            this.stepSeconds = stepSeconds;
            this.steps = steps;
            this.energyDrift = energyDrift;
            this.momentumDrift = momentumDrift;
        }
    }

    final double[] steps;
    final List<OrientationError> errors = new ArrayList<>();
    final List<Drift> drifts = new ArrayList<>();
    /** ns per step of each orientation method, by ordinal (NaN until timed). */
    final double[] nanosPerStep = new double[Orientation.values().length];

    /**
     * Prepare a study; {@link #run} runs every part, tests may run them one by one.
     *
     * @param steps the step sizes (in seconds, largest first)
     */
    RotationStudy(double[] steps) {
        this.steps = steps;
        Arrays.fill(nanosPerStep, Double.NaN);
    }

    /**
     * The step sizes, whatever the report's size: the full sweep's, 1/15 s to 1/1920 s (the
     * errors need the whole range to show their orders, and both parts take well under a
     * second; the report's size only sets how long the cost is timed).
     *
     * @return new array, largest first (in seconds)
     */
    static double[] studySteps() {
        return ReportConfig.of(ReportConfig.Size.FULL).steps();
    }

    /**
     * Run every part.
     *
     * @param meter the report's timing loop (not null)
     * @return the results
     */
    static RotationStudy run(CostMeter meter) {
        RotationStudy study = new RotationStudy(studySteps());
        study.runOrientation();
        study.runRacket();
        study.runCost(meter);
        return study;
    }

    /** The number of steps of h (in seconds) that cover {@code seconds}. */
    static int stepCount(double seconds, double stepSeconds) {
        return (int) Math.round(seconds / stepSeconds);
    }

    /** The sphere at constant ω for {@link #ORIENTATION_SECONDS}, per method and step. */
    void runOrientation() {
        RotationCheck check = new RotationCheck();
        SpinAngle turned = new SpinAngle();
        Matrix3f exact = new Matrix3f();
        for (Orientation method : Orientation.values()) {
            RotationIntegrator integrator =
                    new RotationIntegrator(method, Angular.EXPLICIT, true);
            for (double h : steps) {
                float hf = (float) h;
                int n = stepCount(ORIENTATION_SECONDS, h);
                RigidBody body = new RigidBody(1f, Inertia.sphere(1f, 1f));
                body.setAngularVelocity(OMEGA);
                turned.start(body.orientation, OMEGA);
                for (int i = 0; i < n; ++i) {
                    integrator.step(body, hf);
                    turned.add(body.orientation);
                }
                double seconds = n * (double) hf;
                check.exactRotation(Matrix3f.IDENTITY, OMEGA, seconds, exact);
                errors.add(new OrientationError(method, h, n,
                        check.angleError(body.orientation, exact),
                        check.orthogonalityError(body.orientation),
                        turned.lagRadians(OMEGA.length() * seconds)));
            }
        }
    }

    /** The racket for {@link #RACKET_SECONDS}, per angular method and step. */
    void runRacket() {
        Vector3f scratch = new Vector3f();
        for (Angular method : Angular.values()) {
            RotationIntegrator integrator =
                    new RotationIntegrator(Orientation.EXACT, method, true);
            for (double h : steps) {
                float hf = (float) h;
                int n = stepCount(RACKET_SECONDS, h);
                RigidBody body = new RigidBody(1f, RACKET);
                body.setAngularVelocity(RACKET_OMEGA);
                double energy0 = body.rotationalEnergy(scratch);
                double momentum0 = body.angularMomentum(scratch);
                for (int i = 0; i < n; ++i) {
                    integrator.step(body, hf);
                }
                drifts.add(new Drift(method, h, n,
                        (body.rotationalEnergy(scratch) - energy0) / energy0,
                        (body.angularMomentum(scratch) - momentum0) / momentum0));
            }
        }
    }

    /** One sphere stepped by one orientation method, restarted now and then, as a workload. */
    static final class Spinner implements CostMeter.Workload {
        private final RotationIntegrator integrator;
        private final RigidBody body = new RigidBody(1f, Inertia.sphere(1f, 1f));
        private int sinceRestart;

        Spinner(Orientation method) {
            integrator = new RotationIntegrator(method, Angular.EXPLICIT, true);
            body.setAngularVelocity(OMEGA);
        }

        @Override
        public Object run(int units) {
            for (int i = 0; i < units; ++i) {
                if (sinceRestart == COST_RESTART_STEPS) {
                    body.orientation.loadIdentity();
                    sinceRestart = 0;
                }
                integrator.step(body, COST_STEP_SECONDS);
                ++sinceRestart;
            }
            return body;
        }
    }

    /**
     * Time one step of each orientation method at {@link #COST_STEP_SECONDS}, alternating
     * the methods {@value #COST_PASSES} times and keeping each one's fastest pass, so that a
     * slow moment of a shared machine does not land on one method only.
     */
    void runCost(CostMeter meter) {
        Orientation[] methods = Orientation.values();
        Spinner[] spinners = new Spinner[methods.length];
        for (int m = 0; m < methods.length; ++m) {
            spinners[m] = new Spinner(methods[m]);
            nanosPerStep[m] = Double.POSITIVE_INFINITY;
        }
        for (int pass = 0; pass < COST_PASSES; ++pass) {
            for (int m = 0; m < methods.length; ++m) {
                double nanos = meter.measure(spinners[m], 100).nanosPerUnit();
                nanosPerStep[m] = Math.min(nanosPerStep[m], nanos);
            }
        }
    }

    /** The errors of one method, largest step first. */
    List<OrientationError> errors(Orientation method) {
        List<OrientationError> result = new ArrayList<>();
        for (OrientationError e : errors) {
            if (e.method == method) {
                result.add(e);
            }
        }
        return result;
    }

    /** The drifts of one method, largest step first. */
    List<Drift> drifts(Angular method) {
        List<Drift> result = new ArrayList<>();
        for (Drift d : drifts) {
            if (d.method == method) {
                result.add(d);
            }
        }
        return result;
    }

    /** The fit uses the steps at or below this (in seconds): |ω|h &le; 0.053, asymptotic. */
    static final double FIT_MAX_STEP_SECONDS = 1.0 / 120.0;
    /** Errors at or below this many times the exact step's largest are round-off. */
    static final double ROUND_OFF_MARGIN = 4.0;

    /**
     * The round-off floor of the angle or orthogonality error: {@value #ROUND_OFF_MARGIN}
     * times the exact step's largest error over the sweep, measured in this run (the exact
     * step has no truncation error, so what it shows is float round-off).
     *
     * @param angle true for the angle error, false for the orthogonality error
     * @return the floor (&ge;0)
     */
    double roundOffFloor(boolean angle) {
        double worst = 0.0;
        for (OrientationError e : errors(Orientation.EXACT)) {
            worst = Math.max(worst, angle ? e.angleError : e.orthogonalityError);
        }
        return ROUND_OFF_MARGIN * worst;
    }

    /**
     * The measured order of one method's angle or orthogonality error: {@link OrderFit#slope}
     * through the steps at or below {@link #FIT_MAX_STEP_SECONDS}, stopping at the
     * {@link #roundOffFloor}.
     *
     * @param method the orientation method (not null)
     * @param angle true for the angle error, false for the orthogonality error
     * @return the order, or NaN if fewer than three points lie above round-off and fall
     */
    double order(Orientation method, boolean angle) {
        List<OrientationError> line = new ArrayList<>();
        for (OrientationError e : errors(method)) {
            if (e.stepSeconds <= FIT_MAX_STEP_SECONDS * (1.0 + 1e-12)) {
                line.add(e);
            }
        }
        double[] h = new double[line.size()];
        double[] e = new double[line.size()];
        for (int i = 0; i < h.length; ++i) {
            h[i] = line.get(i).stepSeconds;
            e[i] = angle ? line.get(i).angleError : line.get(i).orthogonalityError;
        }
        return OrderFit.slope(h, e, roundOffFloor(angle));
    }

    /**
     * The largest relative energy or |L| drift of one angular method over the sweep, in size.
     *
     * @param method the angular method (not null)
     * @param energy true for the energy, false for |L|
     * @return the largest |drift| (&ge;0)
     */
    double worstDrift(Angular method, boolean energy) {
        double worst = 0.0;
        for (Drift d : drifts(method)) {
            worst = Math.max(worst, Math.abs(energy ? d.energyDrift : d.momentumDrift));
        }
        return worst;
    }
}
