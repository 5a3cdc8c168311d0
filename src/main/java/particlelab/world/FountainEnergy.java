package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.physics.EnergyLedger;

/**
 * The {@link EnergyLedger} of a {@link Fountain}'s particles (issue 32): its packed pool is
 * no body of a world, so {@link WorldEnergy} does not see it. Kept only while attached
 * ({@link Fountain#setEnergy}): the fountain calls it at a few points of its step, and
 * without it the step does what it always did.
 *
 * <ul>
 * <li><b>kinetic</b>, <b>potential</b>: {@code ½m|V|²} and {@code −m·g·P} summed over the
 * particles in flight after each step ({@code m·g·y}, zero at y = 0);</li>
 * <li><b>drag loss</b>: linear drag as the batch step applies it: evaluated at the step's
 * start velocity V, times the displacement {@code h·V'}, V' the velocity the step moved the
 * particle with (before the ground changed it): {@code b·h·V·V'} per particle;</li>
 * <li><b>impact loss</b>: the kinetic energy the ground's rule took from a particle in
 * contact, {@code ½m(vy'² − vy''²)} (restitution and the resting fix);</li>
 * <li><b>emitted</b>: what each new particle brings in, its {@code ½m|V|² − m·g·P} as the
 * nozzle, the launcher or a burst made it: the source's work. Its own column rather than
 * script work: no body that stays in the scene is pushed, energy enters with matter;</li>
 * <li><b>removed</b>: what each particle going back to the pool takes out (at rest, out of
 * the region, too old, a firework burnt out or burst): its energy as it goes;</li>
 * <li><b>numerical</b>: the rest, from its definition: total now − start − drag loss ... .
 * The ground pushing a particle out of the floor lands here too, as in a world's ledger.</li>
 * </ul>
 * Per particle of {@link Fountain#MASS_KG}, in joules. A step costs O(particles in flight):
 * a copy of their velocities before it, a pass for the drag after the Euler step and a pass
 * for the state at its end; a contact and a particle made or removed cost O(1). Once per
 * step, so the columns add up at every step. Allocates nothing after its construction.
 */
public final class FountainEnergy {

    /** The columns the fountain has: kinetic, potential, drag, impact, emitted, removed. */
    public static final int COLUMNS = EnergyLedger.KINETIC | EnergyLedger.POTENTIAL
            | EnergyLedger.DRAG | EnergyLedger.IMPACT | EnergyLedger.EMITTED
            | EnergyLedger.REMOVED;

    private final Fountain fountain;
    private final int capacity;
    private final EnergyLedger ledger = new EnergyLedger();
    /** V of each particle in flight at the step's start, planar like the pool (m/s). */
    private final float[] velocitiesBefore;
    /** vy of the contacts of the block being resolved, before the ground's rule (m/s). */
    private final float[] contactVelocityY;
    /** g of the fountain's gravity (m/s²). */
    private final Vector3f gravity = new Vector3f();
    /** h of the step under way (s). */
    private float stepSeconds;

    /**
     * Keep the ledger of a fountain, starting from its state now. Attach it with
     * {@link Fountain#setEnergy}.
     *
     * @param fountain the fountain (not null)
     */
    public FountainEnergy(Fountain fountain) {
        if (fountain == null) {
            throw new IllegalArgumentException("fountain must be a fountain, but was null");
        }
        this.fountain = fountain;
        capacity = fountain.getCapacity();
        velocitiesBefore = new float[3 * capacity];
        contactVelocityY = new float[capacity];
        restart();
    }

    /** Start again from the fountain's state now: the start is its energy, every flow 0. */
    public void restart() {
        measure();
        ledger.start();
    }

    /**
     * Access the ledger.
     *
     * @return the live ledger (not null; read it, don't book into it)
     */
    public EnergyLedger getLedger() {
        return ledger;
    }

    /**
     * Calculate one particle's energy {@code ½m|V|² − m·g·P}, in double from its floats.
     *
     * @param index the slot (from 0 to the pool size − 1)
     * @return the energy (in J)
     */
    public double particleJoules(int index) {
        float[] p = fountain.getPositions();
        float[] v = fountain.getVelocities();
        int y = capacity + index;
        int z = 2 * capacity + index;
        double m = Fountain.MASS_KG;
        double squared = (double) v[index] * v[index] + (double) v[y] * v[y]
                + (double) v[z] * v[z];
        return 0.5 * m * squared - m * ((double) gravity.x * p[index]
                + (double) gravity.y * p[y] + (double) gravity.z * p[z]);
    }

    // ------------------------------------------------ the fountain's calls, in its step ----

    /** The step's start: remember every particle in flight's V. */
    void beforeStep(float newStepSeconds) {
        stepSeconds = newStepSeconds;
        copyGravity();
        int live = fountain.countLive();
        float[] v = fountain.getVelocities();
        for (int axis = 0; axis < 3; ++axis) {
            System.arraycopy(v, axis * capacity, velocitiesBefore, axis * capacity, live);
        }
    }

    /** A block's contacts, before the ground's rule: their vy as the Euler step left it. */
    void beforeContacts(int[] found, int from, int to) {
        float[] v = fountain.getVelocities();
        for (int c = from; c < to; ++c) {
            contactVelocityY[c] = v[capacity + found[c]];
        }
    }

    /**
     * A block's contacts, after the ground's rule: its impact loss, and the part of the drag
     * the pass after the step would miss, since it reads vy after the rule, not V'.
     */
    void afterContacts(int[] found, int from, int to) {
        float[] v = fountain.getVelocities();
        double m = Fountain.MASS_KG;
        double b = fountain.getDragCoefficient();
        double impact = 0.0;
        double drag = 0.0;
        for (int c = from; c < to; ++c) {
            int y = capacity + found[c];
            double stepped = contactVelocityY[c];
            double after = v[y];
            impact += 0.5 * m * (stepped * stepped - after * after);
            drag += b * stepSeconds * velocitiesBefore[y] * (stepped - after);
        }
        ledger.addImpactLoss(impact);
        ledger.addDragLoss(drag);
    }

    /**
     * After the Euler step and the ground, before any slot moves: the drag as the step
     * applied it, {@code b·h·V·V'} over every particle that was in flight.
     *
     * @param stepped how many slots the step moved
     */
    void afterEulerStep(int stepped) {
        float[] v = fountain.getVelocities();
        int n = capacity;
        double sum = 0.0;
        for (int i = 0; i < stepped; ++i) {
            sum += (double) velocitiesBefore[i] * v[i]
                    + (double) velocitiesBefore[n + i] * v[n + i]
                    + (double) velocitiesBefore[2 * n + i] * v[2 * n + i];
        }
        ledger.addDragLoss(fountain.getDragCoefficient() * stepSeconds * sum);
    }

    /** A particle goes back to the pool, as it is now. */
    void removed(int index) {
        ledger.addRemoved(particleJoules(index));
    }

    /** A new particle, as its source made it. */
    void emitted(int index) {
        ledger.addEmitted(particleJoules(index));
    }

    /** The step's end: the state of the particles in flight, and the numerical column. */
    void afterStep() {
        measure();
    }

    private void measure() {
        copyGravity();
        float[] p = fountain.getPositions();
        float[] v = fountain.getVelocities();
        int n = capacity;
        int live = fountain.countLive();
        double squared = 0.0;
        double height = 0.0;
        for (int i = 0; i < live; ++i) {
            squared += (double) v[i] * v[i] + (double) v[n + i] * v[n + i]
                    + (double) v[2 * n + i] * v[2 * n + i];
            height += (double) gravity.x * p[i] + (double) gravity.y * p[n + i]
                    + (double) gravity.z * p[2 * n + i];
        }
        double m = Fountain.MASS_KG;
        ledger.beginState();
        ledger.addKinetic(0.5 * m * squared);
        ledger.addPotential(-m * height);
        ledger.endState();
    }

    private void copyGravity() {
        fountain.copyGravity(gravity);
    }
}
