package particlelab.reference;

import com.jme3.math.Vector3f;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.StateSlab;


/**
 * The continuous path of one particle under the forces of its own integrator, in double
 * precision: what the Euler particle would do with an infinitely small step. The demos draw it
 * as the particle's "exact ghost" and compare the two.
 *
 * <p>How it is computed, at each {@link #advance}, from the integrator's forces as they are
 * then (a coefficient changed live takes effect from that moment, for both):
 * <ul>
 * <li>gravity and linear drag only (uniform motion, gravity, gravity + linear drag): the
 * closed form (the report's {@code ClosedForms.gravityLinearDrag}),
 * {@code V(t) = e^{−kt}·V0 + t·φ1(kt)·g},
 * {@code P(t) = P0 + t·φ1(kt)·V0 + t²·φ2(kt)·g}, {@code k = b/m}, evaluated from the state at
 * the last change of the forces (the launch, usually);</li>
 * <li>any other force (quadratic drag, thrust, wind, a spring): classic RK4 with at most
 * {@link #MAX_SUBSTEP_SECONDS} per substep, its stages' accelerations asked from the same
 * integrator ({@link ParticleIntegrator#acceleration}), so it runs the same force code as the
 * Euler step. The accelerations come in float (relative error about 6e-8), which bounds the
 * reference's error near {@code 6e-8·|a|·t²/2}, some 1e-5 m over a 5 s flight: far below the
 * Euler step's own error (tenths of a metre at h = 1/60 s).</li>
 * </ul>
 *
 * <p>Events inside a step are found by bisection on the time within the step, re-evaluating
 * the path (the closed form, or RK4 again from the step's start): the apex, where {@code V.y}
 * turns from positive to zero, and, if asked to stop at the ground, the first crossing of
 * {@code y = 0} going down, where the path then stops. Allocates nothing after construction.
 */
public final class ExactPath {

    /** The longest RK4 substep (in seconds): its error, about h⁴, is then below 1e-12. */
    public static final double MAX_SUBSTEP_SECONDS = 1.0 / 960.0;
    /**
     * The ints {@link #writeState} writes: 23 doubles (the state, the closed form's anchor
     * and forces, the mass, the apex and landing) and 2 booleans.
     */
    public static final int STATE_INTS = 2 * 23 + 2;
    /** Bisections for an event: 60 halve any step below 1e-18 of itself. */
    private static final int BISECTIONS = 60;

    private final ParticleIntegrator integrator;
    private final boolean closedForm;
    private boolean stopsAtGround;
    private double massKg = 1.0;

    /** The state now (m, m/s) and the time since the start (s). */
    private final double[] position = new double[3];
    private final double[] velocity = new double[3];
    private double timeSeconds;

    /** Closed form: the state it starts from, when, and the forces it was made for. */
    private final double[] anchorPosition = new double[3];
    private final double[] anchorVelocity = new double[3];
    private double anchorSeconds;
    private final double[] gravity = new double[3];
    private double rate;

    /** The state at the start of the step being taken, and when that was (s). */
    private double stepStartSeconds;
    private final double[] startPosition = new double[3];
    private final double[] startVelocity = new double[3];
    /** Scratch: a state inside the step, for bisection. */
    private final double[] trialPosition = new double[3];
    private final double[] trialVelocity = new double[3];

    /** RK4 scratch: the stages' positions, velocities and accelerations. */
    private final double[] stagePosition = new double[3];
    private final double[] stageVelocity = new double[3];
    private final double[] positionSum = new double[3];
    private final double[] accelerationSum = new double[3];
    private final double[] stageAcceleration = new double[3];
    private final Particle probe = new Particle();
    private final Vector3f probeAcceleration = new Vector3f();
    private final Vector3f gravityScratch = new Vector3f();

    private boolean landed;
    private double apexSeconds = Double.NaN;
    private double apexHeight = Double.NaN;
    private double landingSeconds = Double.NaN;
    private double landingX = Double.NaN;

    /**
     * Create the exact path of a particle moved by an integrator.
     *
     * @param integrator the integrator holding the particle's forces (not null, not modified;
     *     its forces are read at every {@link #advance})
     */
    public ExactPath(ParticleIntegrator integrator) {
        if (integrator == null) {
            throw new IllegalArgumentException("integrator must not be null");
        }
        this.integrator = integrator;
        boolean onlyGravityAndLinearDrag = true;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force force = integrator.getForce(i);
            onlyGravityAndLinearDrag &= force instanceof Gravity || force instanceof LinearDrag;
        }
        this.closedForm = onlyGravityAndLinearDrag;
    }

    /**
     * Start the path from a launch state, at time 0, with no apex and no landing yet.
     *
     * @param launchPosition P0 (in metres, finite, not null, not modified)
     * @param launchVelocity V0 (in m/s, finite, not null, not modified)
     * @param mass m (in kilograms, finite, &gt;0)
     * @param stopAtGround true to stop the path where it first comes down through y = 0
     */
    public void start(Vector3f launchPosition, Vector3f launchVelocity, float mass,
            boolean stopAtGround) {
        if (!Vector3f.isValidVector(launchPosition) || !Vector3f.isValidVector(launchVelocity)
                || !(mass > 0f) || Float.isInfinite(mass)) {
            throw new IllegalArgumentException("launch P " + launchPosition + " and V "
                    + launchVelocity + " must be finite and the mass (kg) " + mass + " > 0");
        }
        position[0] = launchPosition.x;
        position[1] = launchPosition.y;
        position[2] = launchPosition.z;
        velocity[0] = launchVelocity.x;
        velocity[1] = launchVelocity.y;
        velocity[2] = launchVelocity.z;
        massKg = mass;
        probe.setMass(mass);
        stopsAtGround = stopAtGround;
        timeSeconds = 0.0;
        stepStartSeconds = 0.0;
        landed = false;
        landingSeconds = Double.NaN;
        landingX = Double.NaN;
        if (velocity[1] > 0.0) {
            apexSeconds = Double.NaN;
            apexHeight = Double.NaN;
        } else {
            // Launched level or downward: the highest point is the launch.
            apexSeconds = 0.0;
            apexHeight = position[1];
        }
        if (closedForm) {
            readForces();
            anchor();
        }
    }

    /**
     * Move along the path by some time, stopping at the ground if asked to; once stopped,
     * do nothing. Allocates nothing.
     *
     * @param seconds how long (in seconds, finite, &ge;0)
     */
    public void advance(double seconds) {
        if (!(seconds >= 0.0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("seconds must be finite and >= 0, but was "
                    + seconds);
        }
        if (landed || seconds == 0.0) {
            return;
        }
        probe.setMass((float) massKg);
        if (closedForm && readForces()) {
            // The forces changed since the anchor: start the closed form again from here.
            anchor();
        }
        System.arraycopy(position, 0, startPosition, 0, 3);
        System.arraycopy(velocity, 0, startVelocity, 0, 3);
        double startSeconds = timeSeconds;
        stepStartSeconds = startSeconds;
        stateAt(seconds, position, velocity);
        timeSeconds = startSeconds + seconds;
        if (Double.isNaN(apexSeconds) && startVelocity[1] > 0.0 && !(velocity[1] > 0.0)) {
            double tau = bisect(seconds, true);
            stateAt(tau, trialPosition, trialVelocity);
            apexSeconds = startSeconds + tau;
            apexHeight = trialPosition[1];
        }
        if (stopsAtGround && startPosition[1] >= 0.0 && position[1] < 0.0) {
            double tau = bisect(seconds, false);
            stateAt(tau, position, velocity);
            // Exactly on the ground: the bisection leaves y within round-off of 0.
            position[1] = 0.0;
            timeSeconds = startSeconds + tau;
            landed = true;
            landingSeconds = timeSeconds;
            landingX = position[0];
        }
    }

    /**
     * Test whether the path uses the closed form (gravity and linear drag only), rather than
     * RK4.
     *
     * @return true for the closed form
     */
    public boolean hasClosedForm() {
        return closedForm;
    }

    /** @return the time along the path since the start (in seconds) */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Return one component of the position now.
     *
     * @param axis 0 for x, 1 for y, 2 for z
     * @return P along that axis (in metres)
     */
    public double getPosition(int axis) {
        return position[axis];
    }

    /**
     * Return one component of the velocity now.
     *
     * @param axis 0 for x, 1 for y, 2 for z
     * @return V along that axis (in m/s)
     */
    public double getVelocity(int axis) {
        return velocity[axis];
    }

    /** @return |V| now (in m/s) */
    public double getSpeed() {
        return Math.sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1]
                + velocity[2] * velocity[2]);
    }

    /**
     * Copy the position now into storeResult, rounded to float.
     *
     * @param storeResult storage for the result (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyPosition(Vector3f storeResult) {
        return storeResult.set((float) position[0], (float) position[1], (float) position[2]);
    }

    /**
     * Copy the position at an earlier time of the last step advanced into storeResult: where
     * the path was when a stepped particle landed inside that step. A time at or after now
     * gives the position now (the landing point once the path has stopped). Allocates nothing.
     *
     * @param seconds the time since the start (in seconds, not before the start of the last
     *     step advanced)
     * @param storeResult storage for x, y and z (in metres, length &ge; 3, modified)
     * @return storeResult
     */
    public double[] copyPositionAt(double seconds, double[] storeResult) {
        if (seconds >= timeSeconds) {
            System.arraycopy(position, 0, storeResult, 0, 3);
            return storeResult;
        }
        if (!(seconds >= stepStartSeconds)) {
            throw new IllegalArgumentException("seconds " + seconds
                    + " must lie in the last step advanced, from " + stepStartSeconds + " s");
        }
        stateAt(seconds - stepStartSeconds, storeResult, trialVelocity);
        return storeResult;
    }

    /**
     * Return the distance from a point to the path's position now, in double.
     *
     * @param point the point, e.g. the Euler particle's position (in metres, not null, not
     *     modified)
     * @return |point − P| (in metres)
     */
    public double distanceTo(Vector3f point) {
        double dx = point.x - position[0];
        double dy = point.y - position[1];
        double dz = point.z - position[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** @return true once the path has stopped at the ground */
    public boolean hasLanded() {
        return landed;
    }

    /** @return when the path reached its apex (in seconds; NaN before) */
    public double getApexSeconds() {
        return apexSeconds;
    }

    /** @return the apex's height (in metres; NaN before the apex) */
    public double getApexHeight() {
        return apexHeight;
    }

    /** @return when the path came down through y = 0 (in seconds; NaN before) */
    public double getLandingSeconds() {
        return landingSeconds;
    }

    /** @return where the path came down through y = 0 (x in metres; NaN before) */
    public double getLandingX() {
        return landingX;
    }

    /**
     * Write the path's state (where it is, since when, the closed form's anchor, the apex and
     * landing found), so a step back of the demo puts the ghost back where it was: the next
     * {@link #advance} from the state read back gives the same bits. Allocates nothing.
     *
     * @param slab where to write ({@link #STATE_INTS} ints, not null, modified)
     */
    public void writeState(StateSlab slab) {
        putAll(slab, position);
        putAll(slab, velocity);
        slab.putDouble(timeSeconds);
        putAll(slab, anchorPosition);
        putAll(slab, anchorVelocity);
        slab.putDouble(anchorSeconds);
        putAll(slab, gravity);
        slab.putDouble(rate);
        slab.putDouble(massKg);
        slab.putDouble(apexSeconds);
        slab.putDouble(apexHeight);
        slab.putDouble(landingSeconds);
        slab.putDouble(landingX);
        slab.putBoolean(stopsAtGround);
        slab.putBoolean(landed);
    }

    /**
     * Put back a state {@link #writeState} wrote, in the same order. Allocates nothing.
     *
     * @param slab where to read ({@link #STATE_INTS} ints, not null, modified)
     */
    public void readState(StateSlab slab) {
        getAll(slab, position);
        getAll(slab, velocity);
        timeSeconds = slab.getDouble();
        getAll(slab, anchorPosition);
        getAll(slab, anchorVelocity);
        anchorSeconds = slab.getDouble();
        getAll(slab, gravity);
        rate = slab.getDouble();
        massKg = slab.getDouble();
        probe.setMass((float) massKg);
        apexSeconds = slab.getDouble();
        apexHeight = slab.getDouble();
        landingSeconds = slab.getDouble();
        landingX = slab.getDouble();
        stopsAtGround = slab.getBoolean();
        landed = slab.getBoolean();
    }

    /**
     * Read the summed field acceleration and linear drag rate of the forces.
     *
     * @return true if they differ from those the closed form was anchored with
     */
    private boolean readForces() {
        double gx = 0.0;
        double gy = 0.0;
        double gz = 0.0;
        double drag = 0.0;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force force = integrator.getForce(i);
            if (force instanceof Gravity) {
                ((Gravity) force).copyAcceleration(gravityScratch);
                gx += gravityScratch.x;
                gy += gravityScratch.y;
                gz += gravityScratch.z;
            } else {
                drag += ((LinearDrag) force).getCoefficient();
            }
        }
        double newRate = drag / massKg;
        boolean changed = gx != gravity[0] || gy != gravity[1] || gz != gravity[2]
                || newRate != rate;
        gravity[0] = gx;
        gravity[1] = gy;
        gravity[2] = gz;
        rate = newRate;
        return changed;
    }

    private void anchor() {
        System.arraycopy(position, 0, anchorPosition, 0, 3);
        System.arraycopy(velocity, 0, anchorVelocity, 0, 3);
        anchorSeconds = timeSeconds;
    }

    /**
     * Calculate the state a time tau after the start of the step being taken.
     */
    private void stateAt(double tau, double[] storePosition, double[] storeVelocity) {
        if (closedForm) {
            double t = stepStartSeconds + tau - anchorSeconds;
            double z = rate * t;
            double decay = Math.exp(-z);
            double phi1 = ExactDragStep.phi1(z);
            double phi2 = ExactDragStep.phi2(z);
            for (int i = 0; i < 3; ++i) {
                storePosition[i] = anchorPosition[i] + t * phi1 * anchorVelocity[i]
                        + t * t * phi2 * gravity[i];
                storeVelocity[i] = decay * anchorVelocity[i] + t * phi1 * gravity[i];
            }
            return;
        }
        System.arraycopy(startPosition, 0, storePosition, 0, 3);
        System.arraycopy(startVelocity, 0, storeVelocity, 0, 3);
        int substeps = (int) Math.ceil(tau / MAX_SUBSTEP_SECONDS);
        double h = tau / substeps;
        for (int n = 0; n < substeps; ++n) {
            rungeKuttaStep(storePosition, storeVelocity, h);
        }
    }

    /**
     * Find, by bisection within the step, when V.y reaches 0 (apex) or y reaches 0.
     *
     * @param seconds the step's length (s)
     * @param apex true for V.y, false for y
     * @return the time within the step (s)
     */
    private double bisect(double seconds, boolean apex) {
        double early = 0.0;
        double late = seconds;
        for (int i = 0; i < BISECTIONS; ++i) {
            double mid = 0.5 * (early + late);
            stateAt(mid, trialPosition, trialVelocity);
            double value = apex ? trialVelocity[1] : trialPosition[1];
            if (apex ? value > 0.0 : value >= 0.0) {
                early = mid;
            } else {
                late = mid;
            }
        }
        return 0.5 * (early + late);
    }

    /** One classic RK4 step of the second-order system P' = V, V' = a(P, V). */
    private void rungeKuttaStep(double[] p, double[] v, double h) {
        double half = 0.5 * h;
        // stage 1 at (P, V)
        accelerate(p, v);
        for (int i = 0; i < 3; ++i) {
            positionSum[i] = v[i];
            accelerationSum[i] = stageAcceleration[i];
            stagePosition[i] = p[i] + half * v[i];
            stageVelocity[i] = v[i] + half * stageAcceleration[i];
        }
        // stage 2 at the half step, with stage 1's slopes
        accelerate(stagePosition, stageVelocity);
        for (int i = 0; i < 3; ++i) {
            positionSum[i] += 2.0 * stageVelocity[i];
            accelerationSum[i] += 2.0 * stageAcceleration[i];
            stagePosition[i] = p[i] + half * stageVelocity[i];
            stageVelocity[i] = v[i] + half * stageAcceleration[i];
        }
        // stage 3 at the half step, with stage 2's slopes
        accelerate(stagePosition, stageVelocity);
        for (int i = 0; i < 3; ++i) {
            positionSum[i] += 2.0 * stageVelocity[i];
            accelerationSum[i] += 2.0 * stageAcceleration[i];
            stagePosition[i] = p[i] + h * stageVelocity[i];
            stageVelocity[i] = v[i] + h * stageAcceleration[i];
        }
        // stage 4 at the full step, with stage 3's slopes
        accelerate(stagePosition, stageVelocity);
        double sixth = h / 6.0;
        for (int i = 0; i < 3; ++i) {
            p[i] += sixth * (positionSum[i] + stageVelocity[i]);
            v[i] += sixth * (accelerationSum[i] + stageAcceleration[i]);
        }
    }

    /** The integrator's a = g + F/m at a state, into {@link #stageAcceleration}. */
    private void accelerate(double[] p, double[] v) {
        probe.position.set((float) p[0], (float) p[1], (float) p[2]);
        probe.velocity.set((float) v[0], (float) v[1], (float) v[2]);
        integrator.acceleration(probe, probeAcceleration);
        stageAcceleration[0] = probeAcceleration.x;
        stageAcceleration[1] = probeAcceleration.y;
        stageAcceleration[2] = probeAcceleration.z;
    }

    private static void putAll(StateSlab slab, double[] values) {
        for (int i = 0; i < values.length; ++i) {
            slab.putDouble(values[i]);
        }
    }

    private static void getAll(StateSlab slab, double[] storeResult) {
        for (int i = 0; i < storeResult.length; ++i) {
            storeResult[i] = slab.getDouble();
        }
    }
}
