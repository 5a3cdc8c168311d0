package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Body;
import particlelab.world.GroundStop;
import particlelab.world.StateSlab;

/**
 * One particle of a demo with everything the base class needs to run and draw it: the
 * {@link Body} of the demo's world (the particle, the integrator holding the forces that act
 * on it, its launch state for reset and its flight time), a label, a colour and the record
 * of its states for the export. Create them with {@link DemoState#addParticle}.
 *
 * <p>A particle can be <em>held</em>: it is not stepped (a bullet still in the gun, or one
 * that has landed). A particle told to {@link #stopAtGround() stop at the ground} is held at
 * the point where it crossed {@code y = 0} inside the step, as in the lecture: by its demo
 * world's {@link GroundStop} (the ground plane, the swept test and the stick response), so
 * the landing is a contact the world's listeners and log see like any other, and the stop
 * keeps the landing this class reports.
 */
public final class DemoParticle {

    /** The ints of {@link #writeState}: a flag and the record's counters. */
    static final int STATE_INTS = 1 + TrajectoryRecord.STATE_INTS;

    private String label;
    private final ColorRGBA color;
    private final Body body;
    private final Particle particle;
    private final ParticleIntegrator integrator;
    /** The forces its exact ghost follows: its own integrator's, unless a lane says. */
    private ParticleIntegrator pathIntegrator;
    /**
     * The integrator whose forces move the particle now: its own, unless a part gave it
     * others while it runs (the drag demo's swapped laws, {@link MethodPart#setForces}).
     */
    private ParticleIntegrator forcesNow;
    /** Every state since the launch, for the export. */
    private final TrajectoryRecord record = new TrajectoryRecord();
    /** The demo world's stop at the ground, which keeps the landing. */
    private final GroundStop groundStop;
    /** The particle's place in the ground stop, or -1 if it does not stop there. */
    private int groundIndex = -1;
    /** Set by the base class before each step: the world steps this particle in it. */
    boolean steppedThisStep;
    private boolean parked;
    /** Its exact ghost is never drawn (a twin whose ghost would repeat another's). */
    private boolean ghostHidden;
    /** The particle's place in its demo's list (0 for the first added). */
    final int index;

    DemoParticle(int index, String label, ColorRGBA color, Body body, GroundStop groundStop) {
        this.index = index;
        this.label = label;
        this.groundStop = groundStop;
        this.color = color.clone();
        this.body = body;
        this.particle = body.getParticle();
        this.integrator = body.getIntegrator();
        this.forcesNow = integrator;
        this.pathIntegrator = integrator;
    }

    /**
     * Make the particle stop where it comes down through the ground {@code y = 0}.
     *
     * @return this
     */
    public DemoParticle stopAtGround() {
        if (groundIndex < 0) {
            groundIndex = groundStop.add(body);
        }
        return this;
    }

    /**
     * Test whether the particle stops at the ground.
     *
     * @return true if it does
     */
    public boolean stopsAtGround() {
        return groundIndex >= 0;
    }

    /**
     * Return the label shown next to the particle.
     *
     * @return the label (not null)
     */
    public String getLabel() {
        return label;
    }

    /**
     * Change the label; {@link DemoState#relabel} also changes the text shown.
     *
     * @param newLabel the label (not null)
     */
    void setLabel(String newLabel) {
        if (newLabel == null) {
            throw new IllegalArgumentException("label must be a text, but was null");
        }
        label = newLabel;
    }

    /**
     * Access the colour.
     *
     * @return the live colour (not null, do not modify)
     */
    public ColorRGBA getColor() {
        return color;
    }

    /**
     * Access the particle's body in the demo's world (collision filters, ghost, radius).
     *
     * @return the live body (not null)
     */
    public Body getBody() {
        return body;
    }

    /**
     * Access the particle that the integrator moves.
     *
     * @return the live particle (not null)
     */
    public Particle getParticle() {
        return particle;
    }

    /**
     * Access the integrator with this particle's forces.
     *
     * @return the live integrator (not null)
     */
    public ParticleIntegrator getIntegrator() {
        return integrator;
    }

    /**
     * Access the integrator whose forces move the particle now, for what speaks of the
     * step it takes (the stability line, the step warnings): {@link #getIntegrator()}
     * unless a part gave the particle other forces while it runs.
     *
     * @return the live integrator (not null)
     */
    public ParticleIntegrator getForcesNow() {
        return forcesNow;
    }

    /** Say which integrator's forces move the particle now (null: its own). */
    void setForcesNow(ParticleIntegrator forces) {
        forcesNow = forces == null ? integrator : forces;
    }

    /**
     * Access the integrator whose forces the particle's exact ghost follows: its own, unless
     * its motion is driven from outside (a comparison lane), which names the forces it
     * models.
     *
     * @return the live integrator (not null)
     */
    public ParticleIntegrator getPathIntegrator() {
        return pathIntegrator;
    }

    /**
     * Let the exact ghost follow other forces than the particle's own integrator's. Call
     * before the views are built.
     *
     * @param forces the integrator holding the forces the motion models (not null)
     */
    public void setPathIntegrator(ParticleIntegrator forces) {
        if (forces == null) {
            throw new IllegalArgumentException("path integrator must not be null");
        }
        pathIntegrator = forces;
    }

    /**
     * Access the states recorded since the launch (what the export writes).
     *
     * @return the live record (not null, do not modify)
     */
    public TrajectoryRecord getRecord() {
        return record;
    }

    /**
     * Copy the launch position into storeResult.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult
     */
    public Vector3f copyLaunchPosition(Vector3f storeResult) {
        return body.copyLaunchPosition(storeResult);
    }

    /**
     * Copy the launch velocity into storeResult.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult
     */
    public Vector3f copyLaunchVelocity(Vector3f storeResult) {
        return body.copyLaunchVelocity(storeResult);
    }

    /**
     * Alter the launch state used by resets (and by {@link DemoState#launch}).
     *
     * @param position the launch position (in metres, finite, not null, not modified)
     * @param velocity the launch velocity (in m/s, finite, not null, not modified)
     */
    public void setLaunch(Vector3f position, Vector3f velocity) {
        particle.setState(position, velocity);
        body.setLaunch(position, velocity);
    }

    /**
     * Test whether the particle is held (not stepped).
     *
     * @return true if held
     */
    public boolean isHeld() {
        return body.isHeld();
    }

    /**
     * Hold the particle where it is, or release it.
     *
     * @param newHeld true to stop stepping it
     */
    public void setHeld(boolean newHeld) {
        body.setHeld(newHeld);
    }

    /**
     * Never draw this particle's exact ghost: for a twin launched like another sphere under
     * the same forces, whose ghost would be drawn over that sphere's (or wait at the launch
     * while the twin is held). Call before the views are built.
     */
    public void hideGhost() {
        ghostHidden = true;
    }

    /** @return true if its exact ghost is never drawn ({@link #hideGhost}) */
    public boolean isGhostHidden() {
        return ghostHidden;
    }

    /**
     * Test whether the particle is parked: not used by the demo's current preset, so the HUD
     * leaves it out (the demo holds it somewhere out of the way).
     *
     * @return true if parked
     */
    public boolean isParked() {
        return parked;
    }

    /**
     * Park the particle (leave it out of the HUD) or bring it back.
     *
     * @param newParked true to park it
     */
    public void setParked(boolean newParked) {
        parked = newParked;
    }

    /**
     * Test whether the world stepped the particle in the step just taken (it was not held at
     * the step's start): for a demo's hook or view that follows the particle step by step.
     *
     * @return true if it was stepped
     */
    public boolean wasSteppedThisStep() {
        return steppedThisStep;
    }

    /**
     * Test whether the particle has come down through the ground since its launch.
     *
     * @return true if it landed
     */
    public boolean hasLanded() {
        return groundIndex >= 0 && groundStop.hasLanded(groundIndex);
    }

    /**
     * Return where the particle crossed the ground, interpolated inside the step.
     *
     * @return x (in metres; NaN if it has not landed)
     */
    public float getLandingX() {
        return groundIndex < 0 ? Float.NaN : groundStop.getLandingX(groundIndex);
    }

    /**
     * Return the simulated time of the landing since the launch.
     *
     * @return the time (in seconds; NaN if it has not landed)
     */
    public double getLandingSeconds() {
        return groundIndex < 0 ? Double.NaN : groundStop.getLandingSeconds(groundIndex);
    }

    /**
     * Return the simulated time this particle has been stepped since its launch: its body's
     * ({@link Body#getFlightSeconds()}; during a step's contacts, the step's start).
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getFlightSeconds() {
        return body.getFlightSeconds();
    }

    /**
     * Access the state the step just taken left the particle in, as the Euler step gave it:
     * on its landing step the state below the ground that the ground stop kept before it
     * moved the particle to the crossing (what {@code trajectory --until-ground} prints
     * last), else the particle itself.
     *
     * @return the live state (not null, do not modify)
     */
    Particle getSteppedState() {
        if (groundIndex >= 0 && groundStop.hasLandedThisStep(groundIndex)) {
            return groundStop.getStateBelowGround(groundIndex);
        }
        return particle;
    }

    /**
     * Write the particle's own per-step state (whether it was stepped, the export record's
     * counters) into a state slab: {@link #STATE_INTS} ints. Its launch state and flight time
     * are its body's, its landing the ground stop's: each is recorded there. Allocates
     * nothing.
     */
    void writeState(StateSlab slab) {
        slab.putBoolean(steppedThisStep);
        record.writeState(slab);
    }

    /** Read back what {@link #writeState} wrote. */
    void readState(StateSlab slab) {
        steppedThisStep = slab.getBoolean();
        record.readState(slab);
    }

    /** Put the particle back to its launch state, not held, not landed, flight time 0. */
    void restart() {
        // A launch is no step: the body stands where it is for the view, not between states.
        body.restart();
        if (groundIndex >= 0) {
            groundStop.restart(groundIndex);
        }
        record.clear();
    }
}
