package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.rigid.RigidBody;

/**
 * The simulation of one scene: its bodies, collision rules and listeners, and the one
 * {@link #step} every demo, command and test uses. The {@link SimulationClock} decides the
 * steps (it is the accumulator); the world takes them.
 *
 * <p>One step, in order (index loops over pooled objects: nothing is allocated once a scene
 * has met its largest number of contacts):
 * <ol>
 * <li>{@link StepListener#beforeStep} (scripts set kinematic velocities here);</li>
 * <li><b>integrate</b> every body not held with its own {@link ParticleIntegrator}, the
 * lecture's semi-implicit Euler step {@code V += h·a, P += h·V}, and then, for a body with a
 * rotation part ({@link Body#setRotation}), its rotation step (ω, then R): the only thing
 * that moves a body between contacts. Within the step each body then moves on the straight
 * segment from its previous position to its new one;</li>
 * <li><b>swept contacts</b>, earliest first: the {@link Detection#SWEPT} rules find the first
 * time of impact ahead of every body on its segment; the earliest contact goes through the
 * prologue and, if accepted, its bodies are put where they are at that moment, resolved, and
 * sent on along new straight segments with their new velocities for the rest of the step.
 * Then the rules look again, up to {@link #getMaxImpactsPerStep()} impacts a step; at the
 * cap, bodies with an impact still ahead stay at their last contact for the rest of the step,
 * and the cap is counted ({@link #getCapHits()});</li>
 * <li><b>overlap contacts</b>: the {@link Detection#OVERLAP} rules list every touching pair at
 * the step's end; each goes through the prologue; the accepted ones are resolved worst
 * first (the fastest closing, then the deepest), refreshing the others after each, up to
 * {@link #getMaxResolutionIterations()} resolutions (Cyclone's resolver);</li>
 * <li><b>epilogue</b>: {@link ContactListener#resolved} for every resolved contact of the
 * step, in time order, then every contact goes into the {@link ContactLog}; bodies destroyed
 * during the step leave the world only now; then the step counts into the world's time and
 * the flight time of every body it integrated ({@link Body#getFlightSeconds()});</li>
 * <li>{@link StepListener#afterStep}: listeners observe the step (records, readouts, views);
 * they move nothing. A demo that needs another simulation beside this one steps it beside the
 * world, with the same clock, not inside its step.</li>
 * </ol>
 * The prologue runs the world's own filters first (ghosts, collision groups and masks,
 * one-way surfaces), then each {@link ContactListener#accept}; an accepted contact faster
 * than the hit threshold queues an event in {@link #getImpacts()}.
 *
 * <p>A step that would leave a body non-finite throws a {@link NonFiniteStepException} (from
 * the integrator, or from the world after a contact); the bodies already stepped keep their
 * new state. Not thread-safe.
 */
public final class World implements SimulationClock.Stepper, StateRecord {

    /** The default cap on swept impacts in one step. */
    public static final int DEFAULT_MAX_IMPACTS_PER_STEP = 16;
    /** The default cap on overlap resolutions in one step. */
    public static final int DEFAULT_MAX_RESOLUTION_ITERATIONS = 64;
    /** Overlap contacts closing slower than this are done (in m/s): float round-off. */
    static final float CLOSING_TOLERANCE = 1e-6f;
    /**
     * Overlap contacts shallower than this are done (in metres): the "slop" that stops the
     * position corrections of a row of touching balls from bouncing back and forth between
     * neighbours for ever (Box2D's slop is 5 mm).
     */
    static final float PENETRATION_TOLERANCE = 1e-4f;

    private static final CollisionRule[] NO_RULES = {};
    private static final ContactListener[] NO_CONTACT_LISTENERS = {};
    private static final StepListener[] NO_STEP_LISTENERS = {};
    private static final BodyListener[] NO_BODY_LISTENERS = {};
    /** The audit's floats per body: P, V, then R (9) and ω of a rotation part. */
    private static final int AUDIT_FLOATS = 18;

    /** The world's ints in a state record before its lists and bodies. */
    private static final int STATE_HEADER_INTS = 2 + 2 + 2 + 1 + 2 + 1 + 1 + 2;

    private final List<Body> bodies = new ArrayList<>();
    private final List<Body> recycled = new ArrayList<>();
    /**
     * Every body this world ever created, in creation order: the first {@link #poolSize}
     * are in use (alive or recycled); the rest were created after a state that was put back,
     * and are handed out again in the same order.
     */
    private final List<Body> pool = new ArrayList<>();
    private int poolSize;
    /** Every integrator a body was given, so a state names a body's by its place here. */
    private final List<ParticleIntegrator> integrators = new ArrayList<>();
    /** Scratch for {@link #readState}: which pooled bodies were alive before it. */
    private boolean[] wasAlive = new boolean[0];
    private final List<Body> removals = new ArrayList<>();
    /** Listener and rule arrays are replaced on change, so a step's loops never see one. */
    private CollisionRule[] rules = NO_RULES;
    private ContactListener[] contactListeners = NO_CONTACT_LISTENERS;
    private StepListener[] stepListeners = NO_STEP_LISTENERS;
    private BodyListener[] bodyListeners = NO_BODY_LISTENERS;
    private final Contacts candidates = new Contacts();
    private final Contacts stepContacts = new Contacts();
    private final ContactLog log;
    private final Impacts impacts = new Impacts(Impacts.DEFAULT_CAPACITY);
    /** Scratch: a front normal (unit). */
    private final Vector3f frontNormal = new Vector3f();
    /** Scratch: a body's position at a contact (m). */
    private final Vector3f atContact = new Vector3f();

    private double timeSeconds;
    private long stepCount;
    private long nextSequence;
    private int nextBodyId;
    private long capHits;
    private boolean lastStepHitCap;
    private boolean stepping;
    /** Check that no step listener moves a body ({@link #setAuditingListeners}). */
    private boolean auditingListeners;
    /** The bodies' states after the epilogue, for the audit. */
    private float[] audit = new float[0];
    private int maxImpactsPerStep = DEFAULT_MAX_IMPACTS_PER_STEP;
    private int maxResolutionIterations = DEFAULT_MAX_RESOLUTION_ITERATIONS;

    /**
     * Create an empty world with a log of {@link ContactLog#DEFAULT_CAPACITY} entries.
     */
    public World() {
        this(ContactLog.DEFAULT_CAPACITY);
    }

    /**
     * Create an empty world.
     *
     * @param logCapacity the most contacts the log keeps (&ge;1)
     */
    public World(int logCapacity) {
        log = new ContactLog(logCapacity);
    }

    /**
     * Add a dynamic body, in flight, launched from its current state (recycling a destroyed
     * body if there is one, so spawning in a running scene allocates nothing once warm).
     *
     * @param integrator its forces (not null, may be shared)
     * @param position P0 (in metres, finite, not null, copied)
     * @param velocity V0 (in m/s, finite, not null, copied)
     * @param massKg m (in kg, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &ge;0)
     * @return the body (not null)
     */
    public Body addBody(ParticleIntegrator integrator, Vector3f position, Vector3f velocity,
            float massKg, float radiusMetres) {
        int last = recycled.size() - 1;
        Body body;
        if (last >= 0) {
            body = recycled.get(last);
        } else if (poolSize < pool.size()) {
            body = pool.get(poolSize);
        } else {
            body = new Body();
            body.poolIndex = pool.size();
        }
        try {
            body.reset(nextBodyId, integrator, position, velocity, massKg, radiusMetres);
        } catch (IllegalArgumentException bad) {
            if (last < 0) {
                // A new body refused: it joins the pool as a spare, as a recycled one stays.
                if (body.poolIndex == pool.size()) {
                    pool.add(body);
                }
                ++poolSize;
                recycled.add(body);
            }
            throw bad;
        }
        if (last >= 0) {
            recycled.remove(last);
        } else {
            if (body.poolIndex == pool.size()) {
                pool.add(body);
            }
            ++poolSize;
        }
        if (indexOfIntegrator(integrator) < 0) {
            integrators.add(integrator);
        }
        ++nextBodyId;
        body.inWorld = true;
        bodies.add(body);
        BodyListener[] listeners = bodyListeners;
        for (int i = 0; i < listeners.length; ++i) {
            listeners[i].bodyAdded(this, body);
        }
        return body;
    }

    /**
     * Let another integrator move a body from its next integration on: a demo's visible
     * choice of how its bodies step (the drag demo's {@code method} and drag laws). Allowed
     * between steps and in {@link StepListener#beforeStep}; the integrator is remembered for
     * state records (which name a body's integrator by its place), so the first time an
     * integrator is given may allocate, never again.
     *
     * @param body a body of this world (not null)
     * @param integrator its new forces (not null, may be shared)
     */
    public void setIntegrator(Body body, ParticleIntegrator integrator) {
        getPoolIndex(body);
        if (integrator == null) {
            throw new IllegalArgumentException("integrator must be an integrator, but was null");
        }
        if (indexOfIntegrator(integrator) < 0) {
            integrators.add(integrator);
        }
        body.setIntegrator(integrator);
    }

    /**
     * Destroy a body: during a step it leaves after the epilogue (so no loop is corrupted and
     * every contact of the step still sees it); otherwise at once. Destroying a body already
     * waiting to leave does nothing.
     *
     * @param body a body of this world (not null)
     */
    public void destroy(Body body) {
        if (body == null || !body.inWorld || bodies.indexOf(body) < 0) {
            throw new IllegalArgumentException(
                    "body must be in this world, but was " + body);
        }
        if (stepping) {
            if (!body.removalPending) {
                body.removalPending = true;
                removals.add(body);
            }
            return;
        }
        remove(body);
    }

    /**
     * Count the bodies in the world.
     *
     * @return the count (&ge;0)
     */
    public int countBodies() {
        return bodies.size();
    }

    /**
     * Access a body.
     *
     * @param index which one, in the order added (&ge;0, &lt;{@link #countBodies()})
     * @return the live body (not null)
     */
    public Body getBody(int index) {
        return bodies.get(index);
    }

    /**
     * Count the destroyed bodies kept for reuse.
     *
     * @return the count (&ge;0)
     */
    public int countRecycledBodies() {
        return recycled.size();
    }

    /**
     * Add a collision rule.
     *
     * @param rule the rule (not null)
     */
    public void addRule(CollisionRule rule) {
        rules = append(rules, rule, new CollisionRule[rules.length + 1]);
    }

    /**
     * Remove a collision rule.
     *
     * @param rule a rule added before (not null)
     */
    public void removeRule(CollisionRule rule) {
        rules = without(rules, rule, new CollisionRule[Math.max(0, rules.length - 1)]);
    }

    /**
     * Count the collision rules.
     *
     * @return the count (&ge;0)
     */
    public int countRules() {
        return rules.length;
    }

    /**
     * Access a collision rule.
     *
     * @param index which one, in the order added
     * @return the rule (not null)
     */
    public CollisionRule getRule(int index) {
        return rules[index];
    }

    /**
     * Add a contact listener (prologue and epilogue).
     *
     * @param listener the listener (not null)
     */
    public void addContactListener(ContactListener listener) {
        contactListeners = append(contactListeners, listener,
                new ContactListener[contactListeners.length + 1]);
    }

    /**
     * Remove a contact listener.
     *
     * @param listener a listener added before (not null)
     */
    public void removeContactListener(ContactListener listener) {
        contactListeners = without(contactListeners, listener,
                new ContactListener[Math.max(0, contactListeners.length - 1)]);
    }

    /**
     * Count the contact listeners.
     *
     * @return the count (&ge;0)
     */
    public int countContactListeners() {
        return contactListeners.length;
    }

    /**
     * Add a step listener.
     *
     * @param listener the listener (not null)
     */
    public void addStepListener(StepListener listener) {
        stepListeners = append(stepListeners, listener,
                new StepListener[stepListeners.length + 1]);
    }

    /**
     * Remove a step listener.
     *
     * @param listener a listener added before (not null)
     */
    public void removeStepListener(StepListener listener) {
        stepListeners = without(stepListeners, listener,
                new StepListener[Math.max(0, stepListeners.length - 1)]);
    }

    /**
     * Count the step listeners.
     *
     * @return the count (&ge;0)
     */
    public int countStepListeners() {
        return stepListeners.length;
    }

    /**
     * Add a body listener.
     *
     * @param listener the listener (not null)
     */
    public void addBodyListener(BodyListener listener) {
        bodyListeners = append(bodyListeners, listener,
                new BodyListener[bodyListeners.length + 1]);
    }

    /**
     * Remove a body listener.
     *
     * @param listener a listener added before (not null)
     */
    public void removeBodyListener(BodyListener listener) {
        bodyListeners = without(bodyListeners, listener,
                new BodyListener[Math.max(0, bodyListeners.length - 1)]);
    }

    /**
     * Count the body listeners.
     *
     * @return the count (&ge;0)
     */
    public int countBodyListeners() {
        return bodyListeners.length;
    }

    /**
     * Access the log of every contact.
     *
     * @return the live log (not null)
     */
    public ContactLog getLog() {
        return log;
    }

    /**
     * Access the prologue's queue of impact events (flashes, sounds).
     *
     * @return the live queue (not null)
     */
    public Impacts getImpacts() {
        return impacts;
    }

    /**
     * Return the simulated time: the sum of the steps taken since the start or restart.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Count the steps taken since the start or restart.
     *
     * @return the count (&ge;0)
     */
    public long getStepCount() {
        return stepCount;
    }

    /** @return the most swept impacts handled in one step (&ge;1) */
    public int getMaxImpactsPerStep() {
        return maxImpactsPerStep;
    }

    /**
     * Alter the cap on swept impacts in one step.
     *
     * @param cap the most impacts (&ge;1)
     */
    public void setMaxImpactsPerStep(int cap) {
        if (cap < 1) {
            throw new IllegalArgumentException("impacts per step must be >= 1, but was " + cap);
        }
        maxImpactsPerStep = cap;
    }

    /** @return the most overlap resolutions in one step (&ge;1) */
    public int getMaxResolutionIterations() {
        return maxResolutionIterations;
    }

    /**
     * Alter the cap on overlap resolutions in one step.
     *
     * @param cap the most resolutions (&ge;1)
     */
    public void setMaxResolutionIterations(int cap) {
        if (cap < 1) {
            throw new IllegalArgumentException(
                    "resolution iterations must be >= 1, but was " + cap);
        }
        maxResolutionIterations = cap;
    }

    /**
     * Count the steps that reached a cap with contacts left over.
     *
     * @return the count (&ge;0)
     */
    public long getCapHits() {
        return capHits;
    }

    /**
     * Test whether the last step reached a cap with contacts left over.
     *
     * @return true if it did
     */
    public boolean didLastStepHitCap() {
        return lastStepHitCap;
    }

    /**
     * Test whether a step is running (a listener is being called).
     *
     * @return true inside {@link #step}
     */
    public boolean isStepping() {
        return stepping;
    }

    /**
     * Put every body back to its launch state, in flight, and the time, log and impact queue
     * to zero. Not from inside a step: record the wish there and restart after the clock's
     * advance returns.
     */
    public void restart() {
        if (stepping) {
            throw new IllegalStateException("restart() was called inside a step; call it"
                    + " after the step (after clock.advance returns)");
        }
        for (int i = 0; i < bodies.size(); ++i) {
            bodies.get(i).restart();
        }
        timeSeconds = 0.0;
        stepCount = 0L;
        capHits = 0L;
        lastStepHitCap = false;
        log.clear();
        impacts.clear();
    }

    /**
     * Count the ints {@link #writeState} writes now: the counters, the alive and recycled
     * sets, and every pooled body's state.
     *
     * @return the count (&gt;0; grows only when a body is created)
     */
    @Override
    public int countStateInts() {
        return STATE_HEADER_INTS + poolSize * (2 + Body.STATE_INTS);
    }

    /**
     * Write the world's state: time, step count, contact sequence, next body id, cap counts,
     * which bodies are alive (in order) and which recycled, and every body ever created's P,
     * V, last step's bookkeeping, launch state, flags, filters, integrator and rotation part:
     * everything a step reads, so a step from the state read back gives the same bits. The
     * contact log and the impact queue are not state: they record what happened. Allocates
     * nothing.
     *
     * @param slab where to write (not null, modified)
     */
    @Override
    public void writeState(StateSlab slab) {
        if (stepping) {
            throw new IllegalStateException("writeState() was called inside a step");
        }
        slab.putDouble(timeSeconds);
        slab.putLong(stepCount);
        slab.putLong(nextSequence);
        slab.putInt(nextBodyId);
        slab.putLong(capHits);
        slab.putBoolean(lastStepHitCap);
        slab.putInt(poolSize);
        slab.putInt(bodies.size());
        for (int i = 0; i < bodies.size(); ++i) {
            slab.putInt(bodies.get(i).poolIndex);
        }
        slab.putInt(recycled.size());
        for (int i = 0; i < recycled.size(); ++i) {
            slab.putInt(recycled.get(i).poolIndex);
        }
        for (int i = 0; i < poolSize; ++i) {
            Body body = pool.get(i);
            body.writeState(slab, indexOfIntegrator(body.getIntegrator()));
        }
    }

    /**
     * Put back a state {@link #writeState} wrote: bodies alive then and not now come back
     * ({@link BodyListener#bodyAdded}), bodies alive now and not then leave
     * ({@link BodyListener#bodyRemoved}); bodies created since are kept aside and handed out
     * again, in the same order, by the next {@link #addBody}. The impact queue is cleared.
     * Allocates nothing once the scratch fits the pool.
     *
     * @param slab where to read (not null, modified)
     */
    @Override
    public void readState(StateSlab slab) {
        if (stepping) {
            throw new IllegalStateException("readState() was called inside a step");
        }
        if (wasAlive.length < pool.size()) {
            wasAlive = new boolean[pool.size()];
        }
        for (int i = 0; i < pool.size(); ++i) {
            wasAlive[i] = pool.get(i).inWorld;
        }
        timeSeconds = slab.getDouble();
        stepCount = slab.getLong();
        nextSequence = slab.getLong();
        nextBodyId = slab.getInt();
        capHits = slab.getLong();
        lastStepHitCap = slab.getBoolean();
        poolSize = slab.getInt();
        bodies.clear();
        int alive = slab.getInt();
        for (int i = 0; i < alive; ++i) {
            bodies.add(pool.get(slab.getInt()));
        }
        recycled.clear();
        int spare = slab.getInt();
        for (int i = 0; i < spare; ++i) {
            recycled.add(pool.get(slab.getInt()));
        }
        for (int i = 0; i < poolSize; ++i) {
            pool.get(i).readState(slab, integrators);
        }
        for (int i = poolSize; i < pool.size(); ++i) {
            pool.get(i).inWorld = false;
        }
        removals.clear();
        impacts.clear();
        BodyListener[] listeners = bodyListeners;
        for (int i = 0; i < pool.size(); ++i) {
            Body body = pool.get(i);
            if (wasAlive[i] && !body.inWorld) {
                for (int k = 0; k < listeners.length; ++k) {
                    listeners[k].bodyRemoved(this, body);
                }
            } else if (!wasAlive[i] && body.inWorld) {
                for (int k = 0; k < listeners.length; ++k) {
                    listeners[k].bodyAdded(this, body);
                }
            }
        }
    }

    /**
     * Return a body's place in the world's pool (creation order), for a demo's state record
     * that refers to a body.
     *
     * @param body a body of this world, alive or recycled (not null)
     * @return the place (&ge;0)
     */
    public int getPoolIndex(Body body) {
        if (body == null || body.poolIndex >= pool.size() || pool.get(body.poolIndex) != body) {
            throw new IllegalArgumentException("body must be one of this world's, but was "
                    + body);
        }
        return body.poolIndex;
    }

    /**
     * Access a body by its place in the pool ({@link #getPoolIndex}).
     *
     * @param index the place (&ge;0, less than the bodies ever created)
     * @return the body, alive or not (not null)
     */
    public Body getPooledBody(int index) {
        return pool.get(index);
    }

    /**
     * Take one step of h: integrate, detect, prologue, resolve, epilogue (see the class
     * comment).
     *
     * @param stepSeconds h (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if the step would leave a body non-finite
     * @throws IllegalStateException if called from inside a step
     */
    @Override
    public void step(float stepSeconds) {
        if (!(stepSeconds >= 0f) || stepSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "step h (s) must be finite and >= 0, but was " + stepSeconds);
        }
        if (stepping) {
            throw new IllegalStateException("step() was called from inside a step");
        }
        if (stepSeconds == 0f) {
            return;
        }
        stepping = true;
        lastStepHitCap = false;
        try {
            double startSeconds = timeSeconds;
            StepListener[] listeners = stepListeners;
            for (int i = 0; i < listeners.length; ++i) {
                listeners[i].beforeStep(this, stepSeconds);
            }
            integrate(stepSeconds);
            CollisionRule[] stepRules = rules;
            stepContacts.clear();
            sweptContacts(stepRules, stepSeconds, startSeconds);
            overlapContacts(stepRules, stepSeconds, startSeconds);
            epilogue();
            for (int i = 0; i < removals.size(); ++i) {
                remove(removals.get(i));
            }
            removals.clear();
            countFlightTime(stepSeconds);
            timeSeconds = startSeconds + stepSeconds;
            ++stepCount;
            if (auditingListeners) {
                auditBodies(false);
            }
            for (int i = 0; i < listeners.length; ++i) {
                listeners[i].afterStep(this, stepSeconds);
            }
            if (auditingListeners) {
                auditBodies(true);
            }
        } finally {
            stepContacts.clear();
            candidates.clear();
            stepping = false;
        }
    }

    /**
     * Check, after every step, that no {@link StepListener#afterStep} moved a body: the
     * world's rule that listeners observe and move nothing, made testable. With the check
     * on, each step copies every body's state after the epilogue and compares it after the
     * listeners; a difference throws. For tests: the copy allocates as the world grows.
     *
     * @param newAuditing true to check every step from now on
     */
    public void setAuditingListeners(boolean newAuditing) {
        auditingListeners = newAuditing;
    }

    /** Copy or compare every body's position, velocity and rotation (see the audit). */
    private void auditBodies(boolean compare) {
        int size = AUDIT_FLOATS * bodies.size();
        if (audit.length < size) {
            audit = Arrays.copyOf(audit, size);
        }
        for (int i = 0; i < bodies.size(); ++i) {
            Body body = bodies.get(i);
            RigidBody rigid = body.getRigidBody();
            int at = AUDIT_FLOATS * i;
            for (int k = 0; k < AUDIT_FLOATS; ++k) {
                float value;
                if (k < 3) {
                    value = body.particle.position.get(k);
                } else if (k < 6) {
                    value = body.particle.velocity.get(k - 3);
                } else if (rigid == null) {
                    value = 0f;
                } else if (k < 15) {
                    value = rigid.orientation.get((k - 6) / 3, (k - 6) % 3);
                } else {
                    value = rigid.angularVelocity.get(k - 15);
                }
                if (!compare) {
                    audit[at + k] = value;
                } else if (Float.floatToIntBits(audit[at + k]) != Float.floatToIntBits(value)) {
                    throw new IllegalStateException("a step listener moved " + body
                            + " after the step (listeners observe; they move nothing)");
                }
            }
        }
    }

    private void integrate(float stepSeconds) {
        for (int i = 0; i < bodies.size(); ++i) {
            Body body = bodies.get(i);
            body.previousPosition.set(body.particle.position);
            body.previousVelocity.set(body.particle.velocity);
            body.integratedThisStep = !body.isHeld();
            if (body.integratedThisStep) {
                body.getIntegrator().step(body.particle, stepSeconds);
                RigidBody rigid = body.getRigidBody();
                if (rigid != null) {
                    // Translation first, then rotation: the lecture's order (RigidBody.step).
                    body.getRotationIntegrator().step(rigid, stepSeconds);
                }
            }
            body.gainedVelocity.set(body.particle.velocity).subtractLocal(body.previousVelocity);
            body.sweepStart.set(body.previousPosition);
            body.sweepFraction = 0f;
        }
    }

    /**
     * Count the step into the flight time of every body it integrated, once its contacts are
     * over, as the world's own time: during the contacts both are the step's start.
     */
    private void countFlightTime(float stepSeconds) {
        for (int i = 0; i < bodies.size(); ++i) {
            Body body = bodies.get(i);
            if (body.integratedThisStep) {
                body.addFlightSeconds(stepSeconds);
            }
        }
    }

    private void sweptContacts(CollisionRule[] stepRules, float stepSeconds,
            double startSeconds) {
        boolean any = false;
        for (int r = 0; r < stepRules.length; ++r) {
            any |= stepRules[r].getDetection() == Detection.SWEPT;
        }
        if (!any) {
            return;
        }
        int impactsHandled = 0;
        while (true) {
            candidates.clear();
            for (int r = 0; r < stepRules.length; ++r) {
                if (stepRules[r].getDetection() == Detection.SWEPT) {
                    stepRules[r].detect(this, stepSeconds, candidates);
                }
            }
            Contact earliest = null;
            for (int i = 0; i < candidates.size(); ++i) {
                Contact candidate = candidates.get(i);
                if (!settled(candidate)
                        && (earliest == null || candidate.fraction < earliest.fraction)) {
                    earliest = candidate;
                }
            }
            if (earliest == null) {
                break;
            }
            if (impactsHandled == maxImpactsPerStep) {
                noteCapHit();
                holdAtLastContact();
                break;
            }
            ++impactsHandled;
            Contact contact = stepContacts.add();
            contact.copyFrom(earliest);
            contact.timeSeconds = startSeconds + (double) contact.fraction * stepSeconds;
            contact.bodyA.positionAt(contact.fraction, stepSeconds, atContact);
            setPoint(contact, atContact);
            prologue(contact);
            if (contact.isIgnored()) {
                continue;
            }
            moveToContact(contact.bodyA, contact.fraction, stepSeconds);
            moveToContact(contact.bodyB, contact.fraction, stepSeconds);
            contact.rule.getResponse().resolve(contact, stepSeconds);
            finishSegment(contact.bodyA, contact.fraction, stepSeconds);
            finishSegment(contact.bodyB, contact.fraction, stepSeconds);
        }
        candidates.clear();
    }

    /**
     * At the impact cap: every body with an impact still ahead stays where its last contact
     * left it for the rest of the step, rather than passing through what it would hit.
     */
    private void holdAtLastContact() {
        for (int i = 0; i < candidates.size(); ++i) {
            Contact candidate = candidates.get(i);
            if (!settled(candidate)) {
                candidate.bodyA.particle.position.set(candidate.bodyA.sweepStart);
                if (candidate.bodyB != null) {
                    candidate.bodyB.particle.position.set(candidate.bodyB.sweepStart);
                }
            }
        }
    }

    /**
     * Test whether a swept candidate has been dealt with in this step already: its pair was
     * ignored, or resolved at this moment or later (no progress: round-off after a
     * resolution, not a new impact).
     */
    private boolean settled(Contact candidate) {
        for (int i = 0; i < stepContacts.size(); ++i) {
            Contact done = stepContacts.get(i);
            if (done.samePair(candidate)
                    && (done.isIgnored() || candidate.fraction <= done.fraction)) {
                return true;
            }
        }
        return false;
    }

    private void overlapContacts(CollisionRule[] stepRules, float stepSeconds,
            double startSeconds) {
        int first = stepContacts.size();
        candidates.clear();
        for (int r = 0; r < stepRules.length; ++r) {
            if (stepRules[r].getDetection() == Detection.OVERLAP) {
                stepRules[r].detect(this, stepSeconds, candidates);
            }
        }
        for (int i = 0; i < candidates.size(); ++i) {
            Contact contact = stepContacts.add();
            contact.copyFrom(candidates.get(i));
            contact.timeSeconds = startSeconds + stepSeconds;
            setPoint(contact, contact.bodyA.particle.position);
            prologue(contact);
        }
        candidates.clear();
        int count = stepContacts.size();
        for (int iteration = 0; ; ++iteration) {
            Contact worst = null;
            for (int i = first; i < count; ++i) {
                Contact contact = stepContacts.get(i);
                if (contact.isIgnored()) {
                    continue;
                }
                contact.rule.refresh(contact);
                if (needsWork(contact) && (worst == null || worse(contact, worst))) {
                    worst = contact;
                }
            }
            if (worst == null) {
                return;
            }
            if (iteration == maxResolutionIterations) {
                noteCapHit();
                return;
            }
            worst.rule.getResponse().resolve(worst, stepSeconds);
            checkFinite(worst.bodyA);
            checkFinite(worst.bodyB);
        }
    }

    private static boolean needsWork(Contact contact) {
        return contact.closingNow > CLOSING_TOLERANCE
                || contact.penetrationNow > PENETRATION_TOLERANCE;
    }

    /** Worst first: the fastest closing; among contacts not closing, the deepest. */
    private static boolean worse(Contact contact, Contact than) {
        if (contact.closingNow > CLOSING_TOLERANCE || than.closingNow > CLOSING_TOLERANCE) {
            return contact.closingNow > than.closingNow;
        }
        return contact.penetrationNow > than.penetrationNow;
    }

    private void prologue(Contact contact) {
        contact.sequence = nextSequence++;
        Body a = contact.bodyA;
        Body b = contact.bodyB;
        CollisionRule rule = contact.rule;
        if (a.isGhost() || b != null && b.isGhost()) {
            contact.prologue = Contact.Prologue.IGNORED_GHOST;
            return;
        }
        int groupB = b == null ? rule.getGroup() : b.getGroup();
        int maskB = b == null ? rule.getMask() : b.getMask();
        if ((a.getGroup() & maskB) == 0 || (groupB & a.getMask()) == 0) {
            contact.prologue = Contact.Prologue.IGNORED_BY_FILTER;
            return;
        }
        if (b == null && rule.isOneWay() && contact.surface != null
                && a.particle.velocity.dot(contact.surface.copyFrontNormal(frontNormal)) >= 0f) {
            contact.prologue = Contact.Prologue.IGNORED_ONE_WAY;
            return;
        }
        ContactListener[] listeners = contactListeners;
        for (int i = 0; i < listeners.length; ++i) {
            if (!listeners[i].accept(contact, this)) {
                contact.prologue = Contact.Prologue.IGNORED_BY_LISTENER;
                return;
            }
        }
        contact.prologue = Contact.Prologue.ACCEPTED;
        impacts.offer(contact);
    }

    private void epilogue() {
        ContactListener[] listeners = contactListeners;
        for (int i = 0; i < stepContacts.size(); ++i) {
            Contact contact = stepContacts.get(i);
            if (!contact.isIgnored() && contact.resolution != Contact.Resolution.NONE) {
                for (int k = 0; k < listeners.length; ++k) {
                    listeners[k].resolved(contact, this);
                }
            }
            log.record(contact);
        }
    }

    /** The contact point: on A's surface, {@code P_A − r_A·n}. */
    private static void setPoint(Contact contact, Vector3f positionA) {
        float r = contact.bodyA.getRadius();
        Vector3f n = contact.normal;
        contact.point.set(positionA.x - r * n.x, positionA.y - r * n.y, positionA.z - r * n.z);
    }

    private void moveToContact(Body body, float fraction, float stepSeconds) {
        if (body == null) {
            return;
        }
        body.positionAt(fraction, stepSeconds, atContact);
        body.sweepStart.set(atContact);
        body.sweepFraction = fraction;
        body.particle.position.set(atContact);
    }

    /** After a resolution: the rest of the step on a straight line at the new velocity. */
    private void finishSegment(Body body, float fraction, float stepSeconds) {
        if (body == null) {
            return;
        }
        Vector3f p = body.particle.position;
        body.sweepStart.set(p);
        if (!body.isHeld()) {
            float seconds = (1f - fraction) * stepSeconds;
            Vector3f v = body.particle.velocity;
            p.set(p.x + seconds * v.x, p.y + seconds * v.y, p.z + seconds * v.z);
        }
        checkFinite(body);
    }

    private static void checkFinite(Body body) {
        if (body != null && !body.particle.isFinite()) {
            throw new NonFiniteStepException("a contact left body " + body.getId()
                    + " non-finite: " + body);
        }
    }

    private void noteCapHit() {
        if (!lastStepHitCap) {
            ++capHits;
        }
        lastStepHitCap = true;
    }

    private void remove(Body body) {
        bodies.remove(body);
        body.inWorld = false;
        body.removalPending = false;
        BodyListener[] listeners = bodyListeners;
        for (int i = 0; i < listeners.length; ++i) {
            listeners[i].bodyRemoved(this, body);
        }
        recycled.add(body);
    }

    private int indexOfIntegrator(ParticleIntegrator integrator) {
        for (int i = 0; i < integrators.size(); ++i) {
            if (integrators.get(i) == integrator) {
                return i;
            }
        }
        return -1;
    }

    private static <T> T[] append(T[] array, T item, T[] larger) {
        if (item == null) {
            throw new IllegalArgumentException("cannot add null");
        }
        System.arraycopy(array, 0, larger, 0, array.length);
        larger[array.length] = item;
        return larger;
    }

    private static <T> T[] without(T[] array, T item, T[] smaller) {
        int at = -1;
        for (int i = 0; i < array.length; ++i) {
            if (array[i] == item) {
                at = i;
                break;
            }
        }
        if (at < 0) {
            throw new IllegalArgumentException(item + " was never added");
        }
        System.arraycopy(array, 0, smaller, 0, at);
        System.arraycopy(array, at + 1, smaller, at, array.length - at - 1);
        return smaller;
    }
}
