package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationIntegrator;

/**
 * What moves in a {@link World}: a {@link Particle} (P, V, m), the {@link ParticleIntegrator}
 * that moves it (its forces), a radius for the collision rules, its launch state for restarts,
 * and the bookkeeping of the current step.
 *
 * <p>Three kinds of body:
 * <ul>
 * <li><b>dynamic</b> (the default): mass m, inverse mass {@code 1/m}, pushed by impacts;</li>
 * <li><b>kinematic</b>: moved by script, unaffected by any impact (infinite mass, inverse
 * mass 0). Give it an integrator without forces, so it moves {@code P += h·V}, and set V from
 * a {@link StepListener#beforeStep}: the lecture's "motion science" of kinematics;</li>
 * <li><b>held</b>: not integrated and out of every contact (in the gun, stuck, landed).</li>
 * </ul>
 *
 * <p>Bodies are created by {@link World#addBody} and recycled by the world after
 * {@link World#destroy}: forget a body once its {@link BodyListener#bodyRemoved} has run.
 */
public final class Body {

    /** The collision group every body starts in. */
    public static final int DEFAULT_GROUP = 1;
    /** The mask every body starts with: it may touch every group. */
    public static final int ALL_GROUPS = -1;
    /**
     * The most ints one body's state takes in a {@link StateSlab}: 4 numbers, 8 vectors, h's
     * fraction, 5 flags and filters, 2 doubles, 2 flags, and a rotation part's R, ω, τ.
     */
    static final int STATE_INTS = 4 + 8 * 3 + 1 + 5 + 2 * 2 + 2 + 9 + 3 + 3;

    final Particle particle = new Particle();
    /** P at the start of the current (or last) step (in metres). */
    final Vector3f previousPosition = new Vector3f();
    /** V at the start of the current (or last) step (in m/s). */
    final Vector3f previousVelocity = new Vector3f();
    /** V gained from the forces during the current (or last) step, {@code h·a} (in m/s). */
    final Vector3f gainedVelocity = new Vector3f();
    /** Swept detection: where the current straight segment starts (in metres). */
    final Vector3f sweepStart = new Vector3f();
    /** Swept detection: when inside the step the current segment starts (0 to 1). */
    float sweepFraction;
    /** The world integrated this body in the current (or last) step: its flight time grows. */
    boolean integratedThisStep;

    private final Vector3f launchPosition = new Vector3f();
    private final Vector3f launchVelocity = new Vector3f();
    private ParticleIntegrator integrator;
    private float radiusMetres;
    private boolean held;
    private boolean kinematic;
    private boolean ghost;
    private int group;
    private int mask;
    private double flightSeconds;
    private double scriptedSinceSeconds;
    /** The optional rotation part: orientation, ω and inertia about this body's centre. */
    private RigidBody rigidBody;
    /** Steps {@link #rigidBody}'s ω and R after each translation step (null with it). */
    private RotationIntegrator rotationIntegrator;
    private int id;
    /** Where the world's pool keeps this body (its place in creation order). */
    int poolIndex;
    boolean inWorld;
    boolean removalPending;

    Body() {
    }

    /** Make this (new or recycled) body the one {@link World#addBody} describes. */
    void reset(int newId, ParticleIntegrator newIntegrator, Vector3f position,
            Vector3f velocity, float massKg, float newRadiusMetres) {
        if (newIntegrator == null) {
            throw new IllegalArgumentException("integrator must be an integrator, but was null");
        }
        Validate.nonNegative(newRadiusMetres, "body radius (m)");
        particle.setMass(massKg);
        particle.setState(position, velocity);
        id = newId;
        integrator = newIntegrator;
        radiusMetres = newRadiusMetres;
        launchPosition.set(position);
        launchVelocity.set(velocity);
        held = false;
        kinematic = false;
        ghost = false;
        group = DEFAULT_GROUP;
        mask = ALL_GROUPS;
        removalPending = false;
        integratedThisStep = false;
        rigidBody = null;
        rotationIntegrator = null;
        restart();
    }

    /**
     * Put the body back to its launch state: in flight (not held), flight time 0, no script
     * running, standing where it is for a view's blend ({@link #settle}). {@link World#restart}
     * does this for every body; a demo relaunching one shot calls it for that body alone.
     */
    public void restart() {
        particle.setState(launchPosition, launchVelocity);
        held = false;
        flightSeconds = 0.0;
        scriptedSinceSeconds = Double.NaN;
        settle();
    }

    /**
     * Make the bookkeeping of the last step describe a body standing where it is: after a
     * launch or a teleport, so a view that interpolates inside the last step draws the body
     * where it is now.
     */
    public void settle() {
        previousPosition.set(particle.position);
        previousVelocity.set(particle.velocity);
        gainedVelocity.zero();
        sweepStart.set(particle.position);
        sweepFraction = 0f;
    }

    /**
     * Access the particle: its position, velocity and mass.
     *
     * @return the live particle (not null)
     */
    public Particle getParticle() {
        return particle;
    }

    /**
     * Access the position P.
     *
     * @return the live position (in metres, not null)
     */
    public Vector3f getPosition() {
        return particle.position;
    }

    /**
     * Access the velocity V.
     *
     * @return the live velocity (in m/s, not null)
     */
    public Vector3f getVelocity() {
        return particle.velocity;
    }

    /**
     * Copy the position at the start of the last step, for interpolating inside it.
     *
     * @param storeResult storage for the result (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyPreviousPosition(Vector3f storeResult) {
        return storeResult.set(previousPosition);
    }

    /**
     * Copy the velocity at the start of the last step.
     *
     * @param storeResult storage for the result (in m/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyPreviousVelocity(Vector3f storeResult) {
        return storeResult.set(previousVelocity);
    }

    /**
     * Copy the velocity the forces added during the last step, {@code h·a}: what Cyclone's
     * resting-contact fix removes.
     *
     * @param storeResult storage for the result (in m/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyGainedVelocity(Vector3f storeResult) {
        return storeResult.set(gainedVelocity);
    }

    /**
     * Copy where the body's current straight segment of the step starts, for a swept test: the
     * position at the step's start, or at its last contact inside the step.
     *
     * @param storeResult storage for the result (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copySegmentStart(Vector3f storeResult) {
        return storeResult.set(sweepStart);
    }

    /**
     * Return when inside the step the body's current segment starts.
     *
     * @return the fraction of the step (0 to 1)
     */
    public float getSegmentFraction() {
        return sweepFraction;
    }

    /**
     * Return the integrator that moves this body: its forces.
     *
     * @return the integrator (not null, shared)
     */
    public ParticleIntegrator getIntegrator() {
        return integrator;
    }

    /** Let another integrator move this body from its next step (World.setIntegrator). */
    void setIntegrator(ParticleIntegrator newIntegrator) {
        integrator = newIntegrator;
    }

    /**
     * Return the mass.
     *
     * @return m (in kg, &gt;0)
     */
    public float getMass() {
        return particle.getMass();
    }

    /**
     * Return what an impulse j changes the velocity by: {@code 1/m}, or 0 for a kinematic or
     * held body (infinite mass).
     *
     * @return the inverse mass (in 1/kg, &ge;0)
     */
    public float getInverseMass() {
        return kinematic || held ? 0f : 1f / particle.getMass();
    }

    /**
     * Return the radius the collision rules use.
     *
     * @return r (in metres, &ge;0; 0 is a point)
     */
    public float getRadius() {
        return radiusMetres;
    }

    /**
     * Alter the radius.
     *
     * @param newRadiusMetres r (in metres, finite, &ge;0)
     */
    public void setRadius(float newRadiusMetres) {
        radiusMetres = Validate.nonNegative(newRadiusMetres, "body radius (m)");
    }

    /**
     * Copy the launch position into storeResult.
     *
     * @param storeResult storage (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyLaunchPosition(Vector3f storeResult) {
        return storeResult.set(launchPosition);
    }

    /**
     * Copy the launch velocity into storeResult.
     *
     * @param storeResult storage (in m/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyLaunchVelocity(Vector3f storeResult) {
        return storeResult.set(launchVelocity);
    }

    /**
     * Alter the launch state that {@link World#restart} returns to (the current state is not
     * changed).
     *
     * @param position P0 (in metres, finite, not null, copied)
     * @param velocity V0 (in m/s, finite, not null, copied)
     */
    public void setLaunch(Vector3f position, Vector3f velocity) {
        launchPosition.set(Validate.finite(position, "launch position (m)"));
        launchVelocity.set(Validate.finite(velocity, "launch velocity (m/s)"));
    }

    /**
     * Test whether the body is held: not integrated and in no contact.
     *
     * @return true if held
     */
    public boolean isHeld() {
        return held;
    }

    /**
     * Hold or release the body.
     *
     * @param newHeld true to hold it where it is
     */
    public void setHeld(boolean newHeld) {
        held = newHeld;
    }

    /**
     * Test whether the body is kinematic: moved by script, infinite mass in contacts.
     *
     * @return true if kinematic
     */
    public boolean isKinematic() {
        return kinematic;
    }

    /**
     * Make the body kinematic (moved by script, infinite mass) or dynamic.
     *
     * @param newKinematic true for kinematic
     */
    public void setKinematic(boolean newKinematic) {
        kinematic = newKinematic;
    }

    /**
     * Test whether the body is a ghost: every contact it takes part in is ignored by the
     * prologue.
     *
     * @return true if a ghost
     */
    public boolean isGhost() {
        return ghost;
    }

    /**
     * Make the body a ghost (it passes through everything) or solid.
     *
     * @param newGhost true for a ghost
     */
    public void setGhost(boolean newGhost) {
        ghost = newGhost;
    }

    /**
     * Return the collision groups the body belongs to, as bits.
     *
     * @return the group bits ({@link #DEFAULT_GROUP} unless changed)
     */
    public int getGroup() {
        return group;
    }

    /**
     * Return the groups this body may touch, as bits.
     *
     * @return the mask bits ({@link #ALL_GROUPS} unless changed)
     */
    public int getMask() {
        return mask;
    }

    /**
     * Alter the collision filter: two things touch only when each one's group meets the
     * other's mask, {@code (groupA & maskB) != 0 && (groupB & maskA) != 0}.
     *
     * @param newGroup the groups the body belongs to (bits)
     * @param newMask the groups it may touch (bits)
     */
    public void setCollisionFilter(int newGroup, int newMask) {
        group = newGroup;
        mask = newMask;
    }

    /**
     * Return how long the body has been integrated since its launch or restart. A step counts
     * once its contacts are over, as in {@link World#getTimeSeconds()}: during a step's
     * contacts (a rule, a response, a {@link ContactListener}) this is the time at the step's
     * start, so a contact's time since the launch is this plus {@code fraction·h}.
     *
     * @return the flight time (in seconds, &ge;0)
     */
    public double getFlightSeconds() {
        return flightSeconds;
    }

    /**
     * Return when an animation-based response took this body over (a view plays its canned
     * squash or fade from then on).
     *
     * @return the world time (in seconds), or NaN if no script runs
     */
    public double getScriptedSinceSeconds() {
        return scriptedSinceSeconds;
    }

    /**
     * Give the body a rotation part, or take it away: the world then steps the body's
     * translation and then its rotation in each step, as the lecture's "combine with
     * translation" says ({@link RigidBody#step}, in this order). The rigid body must share
     * this body's particle, so there is one centre.
     *
     * @param newRigidBody the orientation, ω, torque and inertia (its particle must be this
     *     body's; null for a point body)
     * @param newIntegrator the rotation step (not null with a rigid body, null without)
     * @return this
     */
    public Body setRotation(RigidBody newRigidBody, RotationIntegrator newIntegrator) {
        if ((newRigidBody == null) != (newIntegrator == null)) {
            throw new IllegalArgumentException("a rotation needs both the rigid body and its"
                    + " integrator, but was given " + newRigidBody + " and " + newIntegrator);
        }
        if (newRigidBody != null && newRigidBody.getParticle() != particle) {
            throw new IllegalArgumentException("the rigid body must share the body's particle"
                    + " (new RigidBody(body.getParticle(), inertia)), but has its own");
        }
        rigidBody = newRigidBody;
        rotationIntegrator = newIntegrator;
        return this;
    }

    /**
     * Access the rotation part.
     *
     * @return the live rigid body, or null for a point body
     */
    public RigidBody getRigidBody() {
        return rigidBody;
    }

    /**
     * Access the rotation step the world uses for this body.
     *
     * @return the integrator, or null for a point body
     */
    public RotationIntegrator getRotationIntegrator() {
        return rotationIntegrator;
    }

    /**
     * Return the body's number in the world, unique among the bodies a world ever created.
     *
     * @return the id (&ge;0)
     */
    public int getId() {
        return id;
    }

    /**
     * Test whether the body is in a world (not destroyed).
     *
     * @return true if in a world
     */
    public boolean isInWorld() {
        return inWorld;
    }

    @Override
    public String toString() {
        return "Body#" + id + "[" + particle + ", r=" + radiusMetres
                + (held ? ", held" : "") + (kinematic ? ", kinematic" : "")
                + (ghost ? ", ghost" : "") + "]";
    }

    void addFlightSeconds(float stepSeconds) {
        flightSeconds += stepSeconds;
    }

    void startScript(double worldSeconds) {
        scriptedSinceSeconds = worldSeconds;
    }

    /**
     * Write everything a step reads of this body into a slab: {@link #STATE_INTS} ints at
     * most (see {@link World#writeState}).
     */
    void writeState(StateSlab slab, int integratorIndex) {
        slab.putInt(id);
        slab.putInt(integratorIndex);
        slab.putFloat(particle.getMass());
        slab.putFloat(radiusMetres);
        slab.putVector(particle.position);
        slab.putVector(particle.velocity);
        slab.putVector(previousPosition);
        slab.putVector(previousVelocity);
        slab.putVector(gainedVelocity);
        slab.putVector(sweepStart);
        slab.putFloat(sweepFraction);
        slab.putVector(launchPosition);
        slab.putVector(launchVelocity);
        slab.putBoolean(held);
        slab.putBoolean(kinematic);
        slab.putBoolean(ghost);
        slab.putInt(group);
        slab.putInt(mask);
        slab.putDouble(flightSeconds);
        slab.putDouble(scriptedSinceSeconds);
        slab.putBoolean(inWorld);
        slab.putBoolean(rigidBody != null);
        if (rigidBody != null) {
            slab.putMatrix(rigidBody.orientation);
            slab.putVector(rigidBody.angularVelocity);
            slab.putVector(rigidBody.torque);
        }
    }

    /**
     * Read back what {@link #writeState} wrote; the rotation part, if written, goes into the
     * body's current one (rotation parts are given at creation and kept).
     */
    void readState(StateSlab slab, List<ParticleIntegrator> integrators) {
        id = slab.getInt();
        integrator = integrators.get(slab.getInt());
        particle.setMass(slab.getFloat());
        radiusMetres = slab.getFloat();
        slab.getVector(particle.position);
        slab.getVector(particle.velocity);
        slab.getVector(previousPosition);
        slab.getVector(previousVelocity);
        slab.getVector(gainedVelocity);
        slab.getVector(sweepStart);
        sweepFraction = slab.getFloat();
        slab.getVector(launchPosition);
        slab.getVector(launchVelocity);
        held = slab.getBoolean();
        kinematic = slab.getBoolean();
        ghost = slab.getBoolean();
        group = slab.getInt();
        mask = slab.getInt();
        flightSeconds = slab.getDouble();
        scriptedSinceSeconds = slab.getDouble();
        inWorld = slab.getBoolean();
        removalPending = false;
        if (slab.getBoolean()) {
            if (rigidBody == null) {
                throw new IllegalStateException("a recorded rotation part for " + this
                        + ", which has none now");
            }
            slab.getMatrix(rigidBody.orientation);
            slab.getVector(rigidBody.angularVelocity);
            slab.getVector(rigidBody.torque);
        }
    }

    /**
     * Copy where a view draws the body between the last two physics states: the lecture's
     * "fix your timestep" blend {@code P_prev + α·(P − P_prev)} of the position at the start
     * of the last step and the position now, α being the accumulator's leftover over h.
     *
     * @param alpha the blend (0: the previous state, 1 or more: the state now, exactly)
     * @param storeResult storage for the result (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyDrawnPosition(float alpha, Vector3f storeResult) {
        return blend(previousPosition, particle.position, alpha, storeResult);
    }

    /**
     * Blend two positions: {@code from + α·(to − from)}, exactly {@code to} for α &ge; 1 and
     * exactly {@code from} for α &le; 0.
     *
     * @param from the earlier state (not null, not modified)
     * @param to the later state (not null, not modified)
     * @param alpha the blend (any; clamped to 0 to 1)
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult
     */
    public static Vector3f blend(Vector3f from, Vector3f to, float alpha,
            Vector3f storeResult) {
        if (!(alpha < 1f)) {
            return storeResult.set(to);
        }
        if (!(alpha > 0f)) {
            return storeResult.set(from);
        }
        return storeResult.set(from.x + alpha * (to.x - from.x),
                from.y + alpha * (to.y - from.y), from.z + alpha * (to.z - from.z));
    }

    /** Compute where the body is at a fraction of the step on its current segment. */
    Vector3f positionAt(float fraction, float stepSeconds, Vector3f storeResult) {
        if (fraction == sweepFraction || held) {
            return storeResult.set(sweepStart);
        }
        float seconds = (fraction - sweepFraction) * stepSeconds;
        Vector3f v = particle.velocity;
        return storeResult.set(sweepStart.x + seconds * v.x, sweepStart.y + seconds * v.y,
                sweepStart.z + seconds * v.z);
    }
}
