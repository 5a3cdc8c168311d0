package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Where the energy goes: the columns of a scene's energy, kept so that they add up at every
 * step (issue 32).
 *
 * <pre>
 *   kinetic + potential + spring
 *       = start + thrust work − drag loss − impact loss + script work
 *         + emitted − removed + numerical
 * </pre>
 * <ul>
 * <li><b>kinetic</b> {@code ½m|V|²} (plus a rigid body's {@code ½ωᵀIω}, added by the caller),
 * <b>potential</b> {@code −m·g·P} of every {@link Gravity} ({@code m·g·y} for g = (0, −g, 0)),
 * <b>spring</b> {@code ½k(|d| − L)²} of every {@link Spring}: the state's energy, measured;</li>
 * <li><b>thrust work</b>, <b>drag loss</b>: the work the forces do <em>as the step applies
 * them</em>: each force evaluated where the step evaluates it (the state at the step's start)
 * times the displacement the step makes, {@code W = F(P, V)·h·V'}, V' the velocity the step
 * moves with (semi-implicit Euler: the new one). Drag loss is {@code −W} of {@link LinearDrag}
 * ({@code b·h·V·V'}), {@link QuadraticDrag}, {@link SlideFormDrag} and a spring's damping;
 * thrust work is W of {@link Thrust} and of any other force (the wind, a student's own);</li>
 * <li><b>impact loss</b>, <b>script work</b>: told by the contacts' responses
 * ({@link #addImpactLoss}, {@link #addScriptWork});</li>
 * <li><b>emitted</b>, <b>removed</b>: the energy particles bring in when a source makes
 * them and take out when they are removed, in a scene whose particles come and go (the
 * fountain: {@link #addEmitted}, {@link #addRemoved});</li>
 * <li><b>numerical</b>: the rest, from its definition: the total now minus the start minus
 * the physics' work. It is the energy the step itself created or destroyed. Gravity alone,
 * semi-implicit Euler: each step changes K + U by exactly {@code −½m·g²h²}, so after n steps
 * numerical = {@code m·g·h·(vy − vy0)/2}.</li>
 * </ul>
 * Energy put in between steps (a launch, a drag with the mouse, a changed parameter) moves
 * the start ({@link #addToStart}): it is not the step's.
 *
 * <p>Everything is summed in double from the float state, so the columns add up to double
 * rounding (about 1e-16 of the largest column per step) and every float the simulation holds
 * is represented exactly. Allocates nothing. Not thread-safe.
 */
public final class EnergyLedger {

    /** Columns: kinetic energy. */
    public static final int KINETIC = 1;
    /** Columns: gravitational potential energy. */
    public static final int POTENTIAL = 1 << 1;
    /** Columns: a spring's elastic energy. */
    public static final int SPRING = 1 << 2;
    /** Columns: work of thrust and other pushing forces. */
    public static final int THRUST = 1 << 3;
    /** Columns: energy lost to drag. */
    public static final int DRAG = 1 << 4;
    /** Columns: energy lost in impacts. */
    public static final int IMPACT = 1 << 5;
    /** Columns: work done by scripts (kinematic bodies). */
    public static final int SCRIPT = 1 << 6;
    /** Columns: energy brought in by particles a source made (the fountain's). */
    public static final int EMITTED = 1 << 7;
    /** Columns: energy taken out by particles removed (the fountain's). */
    public static final int REMOVED = 1 << 8;

    /** The CSV names of the columns, in order: bit i of a column set is name i. */
    private static final String[] COLUMN_NAMES = {"kinetic_J", "potential_J", "spring_J",
        "thrust_work_J", "drag_loss_J", "impact_loss_J", "script_work_J", "emitted_J",
        "removed_J"};
    /** The index of the numerical column in {@link #getColumn}: after the nine others. */
    public static final int NUMERICAL_COLUMN = 9;
    /** The CSV name of the numerical column, always last. */
    public static final String NUMERICAL_NAME = "numerical_J";

    private double startJoules;
    private double kineticJoules;
    private double potentialJoules;
    private double springJoules;
    private double thrustWorkJoules;
    private double dragLossJoules;
    private double impactLossJoules;
    private double scriptWorkJoules;
    private double emittedJoules;
    private double removedJoules;
    private double numericalJoules;
    /** The state's sums while {@link #beginState()} ... {@link #endState()} runs. */
    private double sumKinetic;
    private double sumPotential;
    private double sumSpring;

    /** Scratch: g of one gravity (m/s²). */
    private final Vector3f gravity = new Vector3f();
    /** Scratch: one force (N). */
    private final Vector3f force = new Vector3f();
    /** Scratch: the field accelerations of one force (m/s²). */
    private final Vector3f field = new Vector3f();
    /** Scratch: a spring's anchor (m). */
    private final Vector3f anchor = new Vector3f();

    /**
     * Start from a state already measured ({@link #beginState()}, {@link #addBody},
     * {@link #endState()}): the start is its total, every flow zero.
     */
    public void start() {
        startJoules = total();
        thrustWorkJoules = 0.0;
        dragLossJoules = 0.0;
        impactLossJoules = 0.0;
        scriptWorkJoules = 0.0;
        emittedJoules = 0.0;
        removedJoules = 0.0;
        numericalJoules = 0.0;
    }

    /** Begin measuring a state: the sums of kinetic, potential and spring energy restart. */
    public void beginState() {
        sumKinetic = 0.0;
        sumPotential = 0.0;
        sumSpring = 0.0;
    }

    /**
     * Add one particle's energy to the state being measured: {@code ½m|V|²}, and the potential
     * of its integrator's gravities and springs.
     *
     * @param integrator the particle's forces (not null)
     * @param particle the particle (not null, not modified)
     */
    public void addBody(ParticleIntegrator integrator, Particle particle) {
        sumKinetic += kineticJoules(particle);
        double m = particle.getMass();
        Vector3f p = particle.position;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force each = integrator.getForce(i);
            if (each instanceof Gravity) {
                ((Gravity) each).copyAcceleration(gravity);
                sumPotential -= m * ((double) gravity.x * p.x + (double) gravity.y * p.y
                        + (double) gravity.z * p.z);
            } else if (each instanceof Spring) {
                sumSpring += springJoules((Spring) each, p);
            }
        }
    }

    /**
     * Add kinetic energy the particles do not hold to the state being measured (a rigid
     * body's rotation, {@code ½ωᵀIω}).
     *
     * @param joules the energy (in J)
     */
    public void addKinetic(double joules) {
        sumKinetic += joules;
    }

    /**
     * Add gravitational potential energy to the state being measured, summed by the caller
     * (the fountain's packed particles: {@code −m·g·P} of each).
     *
     * @param joules the energy (in J)
     */
    public void addPotential(double joules) {
        sumPotential += joules;
    }

    /**
     * Finish measuring a state: it becomes the ledger's kinetic, potential and spring columns,
     * and the numerical column follows from its definition.
     */
    public void endState() {
        kineticJoules = sumKinetic;
        potentialJoules = sumPotential;
        springJoules = sumSpring;
        numericalJoules = total() - startJoules - thrustWorkJoules + dragLossJoules
                + impactLossJoules - scriptWorkJoules - emittedJoules + removedJoules;
    }

    /**
     * Book the work the forces did on one particle in one step, as the step applied them:
     * each force at the step's start state times the displacement {@code h·V'}.
     *
     * @param integrator the particle's forces (not null)
     * @param atStart the particle at the step's start: where the step evaluated the forces
     *     (not null, not modified)
     * @param stepSeconds h (in seconds)
     * @param stepVelocity V', the velocity the step moved the particle with (in m/s, not null,
     *     not modified)
     */
    public void addStepWork(ParticleIntegrator integrator, Particle atStart, float stepSeconds,
            Vector3f stepVelocity) {
        double m = atStart.getMass();
        double dx = (double) stepSeconds * stepVelocity.x;
        double dy = (double) stepSeconds * stepVelocity.y;
        double dz = (double) stepSeconds * stepVelocity.z;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force each = integrator.getForce(i);
            if (each instanceof Gravity) {
                continue;
            }
            force.zero();
            field.zero();
            if (each instanceof Spring) {
                dampingForce((Spring) each, atStart, force);
            } else {
                each.addForce(atStart, force);
                each.addFieldAcceleration(atStart, field);
            }
            // W = (F + m·a_field)·h·V'
            double work = (force.x + m * field.x) * dx + (force.y + m * field.y) * dy
                    + (force.z + m * field.z) * dz;
            if (each instanceof Spring || isDrag(each)) {
                // a spring's elastic force is its potential; what is booked is its damping
                dragLossJoules -= work;
            } else {
                thrustWorkJoules += work;
            }
        }
    }

    /**
     * Book energy lost in an impact.
     *
     * @param joules the kinetic energy the impact took (in J, usually &ge;0)
     */
    public void addImpactLoss(double joules) {
        impactLossJoules += joules;
    }

    /**
     * Book work a script did (a kinematic body's motion, a paddle's push).
     *
     * @param joules the work (in J)
     */
    public void addScriptWork(double joules) {
        scriptWorkJoules += joules;
    }

    /**
     * Book energy drag took, computed by the caller as the step applied the drag (the
     * fountain's packed particles: {@code b·h·V·V'} each).
     *
     * @param joules the energy taken (in J, &ge;0 for drag that opposes V)
     */
    public void addDragLoss(double joules) {
        dragLossJoules += joules;
    }

    /**
     * Book the energy a new particle brings in: its {@code ½m|V|² − m·g·P} as a source made
     * it (a nozzle's drop, a burst's star).
     *
     * @param joules the energy (in J)
     */
    public void addEmitted(double joules) {
        emittedJoules += joules;
    }

    /**
     * Book the energy a removed particle takes out: its {@code ½m|V|² − m·g·P} as it goes.
     *
     * @param joules the energy (in J)
     */
    public void addRemoved(double joules) {
        removedJoules += joules;
    }

    /**
     * Move the start by energy put in between steps (a launch, a drag, a changed parameter).
     *
     * @param joules the energy put in (in J; negative: taken out)
     */
    public void addToStart(double joules) {
        startJoules += joules;
    }

    /**
     * Tell which columns the forces of an integrator give ({@link #POTENTIAL},
     * {@link #SPRING}, {@link #THRUST}, {@link #DRAG}; a spring with damping gives DRAG too).
     *
     * @param integrator the forces (not null)
     * @return the columns, OR-ed
     */
    public static int columnsOf(ParticleIntegrator integrator) {
        int columns = 0;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force each = integrator.getForce(i);
            if (each instanceof Gravity) {
                columns |= POTENTIAL;
            } else if (each instanceof Spring) {
                columns |= SPRING;
                if (((Spring) each).getDamping() > 0f) {
                    columns |= DRAG;
                }
            } else if (isDrag(each)) {
                columns |= DRAG;
            } else {
                columns |= THRUST;
            }
        }
        return columns;
    }

    /**
     * Write the CSV header of a set of columns: {@code t}, the columns in the order
     * {@code kinetic_J, potential_J, spring_J, thrust_work_J, drag_loss_J, impact_loss_J,
     * script_work_J, emitted_J, removed_J} (those not in the set left out), then
     * {@code numerical_J}.
     *
     * @param columns the set, OR-ed ({@link #KINETIC} ...)
     * @param prefix what comes before the energy columns, e.g. {@code "t"} (not null)
     * @return the header (not null)
     */
    public static String csvHeader(int columns, String prefix) {
        StringBuilder header = new StringBuilder(prefix);
        for (int i = 0; i < COLUMN_NAMES.length; ++i) {
            if ((columns & (1 << i)) != 0) {
                header.append(',').append(COLUMN_NAMES[i]);
            }
        }
        return header.append(',').append(NUMERICAL_NAME).toString();
    }

    /**
     * Count the values of a CSV row of a set of columns, {@code numerical_J} included.
     *
     * @param columns the set, OR-ed
     * @return the count (&ge;1)
     */
    public static int countColumns(int columns) {
        return Integer.bitCount(columns & ((1 << COLUMN_NAMES.length) - 1)) + 1;
    }

    /**
     * Return the value of a column.
     *
     * @param index which: 0 to 8 the columns in {@link #csvHeader}'s order as bits
     *     ({@code 1 << index}), 9 the numerical column
     * @return the value (in J)
     */
    public double getColumn(int index) {
        switch (index) {
            case 0:
                return kineticJoules;
            case 1:
                return potentialJoules;
            case 2:
                return springJoules;
            case 3:
                return thrustWorkJoules;
            case 4:
                return dragLossJoules;
            case 5:
                return impactLossJoules;
            case 6:
                return scriptWorkJoules;
            case 7:
                return emittedJoules;
            case 8:
                return removedJoules;
            case NUMERICAL_COLUMN:
                return numericalJoules;
            default:
                throw new IllegalArgumentException("column index must be from 0 to "
                        + NUMERICAL_COLUMN + ", but was " + index);
        }
    }

    /**
     * Calculate a particle's kinetic energy {@code ½m|V|²}, in double from its floats.
     *
     * @param particle the particle (not null, not modified)
     * @return the energy (in J)
     */
    public static double kineticJoules(Particle particle) {
        Vector3f v = particle.velocity;
        double squared = (double) v.x * v.x + (double) v.y * v.y + (double) v.z * v.z;
        return 0.5 * particle.getMass() * squared;
    }

    /**
     * Calculate a spring's elastic energy {@code ½k(|d| − L)²} at a position. Allocates
     * nothing.
     *
     * @param spring the spring (not null)
     * @param position P (in metres, not null, not modified)
     * @return the energy (in J)
     */
    public double springJoules(Spring spring, Vector3f position) {
        spring.copyAnchor(anchor);
        double dx = (double) position.x - anchor.x;
        double dy = (double) position.y - anchor.y;
        double dz = (double) position.z - anchor.z;
        double stretch = Math.sqrt(dx * dx + dy * dy + dz * dz) - spring.getRestLength();
        return 0.5 * spring.getSpringConstant() * stretch * stretch;
    }

    /** @return the start's energy, with what was put in between steps (J) */
    public double getStartJoules() {
        return startJoules;
    }

    /** @return the kinetic energy now (J) */
    public double getKineticJoules() {
        return kineticJoules;
    }

    /** @return the gravitational potential energy now, zero at the origin (J) */
    public double getPotentialJoules() {
        return potentialJoules;
    }

    /** @return the springs' elastic energy now (J) */
    public double getSpringJoules() {
        return springJoules;
    }

    /** @return the work thrust and other pushing forces did since the start (J) */
    public double getThrustWorkJoules() {
        return thrustWorkJoules;
    }

    /** @return the energy drag took since the start (J, &ge;0 for drag that opposes V) */
    public double getDragLossJoules() {
        return dragLossJoules;
    }

    /** @return the energy impacts took since the start (J) */
    public double getImpactLossJoules() {
        return impactLossJoules;
    }

    /** @return the work scripts did since the start (J) */
    public double getScriptWorkJoules() {
        return scriptWorkJoules;
    }

    /** @return the energy new particles brought in since the start (J) */
    public double getEmittedJoules() {
        return emittedJoules;
    }

    /** @return the energy removed particles took out since the start (J) */
    public double getRemovedJoules() {
        return removedJoules;
    }

    /** @return the energy the steps themselves created (positive) or destroyed (J) */
    public double getNumericalJoules() {
        return numericalJoules;
    }

    /** @return kinetic + potential + spring now (J) */
    public double total() {
        return kineticJoules + potentialJoules + springJoules;
    }

    /** The force of a spring's damping alone, {@code −c·(V·u)·u}, u along the spring. */
    private void dampingForce(Spring spring, Particle particle, Vector3f storeResult) {
        float c = spring.getDamping();
        if (c == 0f) {
            return;
        }
        spring.copyAnchor(anchor);
        Vector3f p = particle.position;
        double dx = (double) p.x - anchor.x;
        double dy = (double) p.y - anchor.y;
        double dz = (double) p.z - anchor.z;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (!(length >= Spring.MIN_LENGTH)) {
            return;
        }
        Vector3f v = particle.velocity;
        double along = (v.x * dx + v.y * dy + v.z * dz) / length;
        double push = -c * along / length;
        storeResult.set((float) (push * dx), (float) (push * dy), (float) (push * dz));
    }

    private static boolean isDrag(Force force) {
        return force instanceof LinearDrag || force instanceof QuadraticDrag
                || force instanceof SlideFormDrag;
    }
}
