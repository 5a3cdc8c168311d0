package particlelab.reference;

/**
 * The stepping methods compared, with what theory says about each: the order of the global
 * error and the stability limit under linear drag ({@code h < factor·m/b}; gravity does not
 * change it). Values from docs/numerics.md.
 */
public enum Scheme {

    /** Forward (explicit) Euler: {@code P ← P + h·V} with the old V, then {@code V ← V + h·a}. */
    FORWARD_EULER("forward-euler", "forward Euler", "forward Euler", 1.0, 2.0),
    /**
     * The lecture's semi-implicit Euler: the shared {@code ParticleIntegrator} itself, in float
     * (jME) precision.
     */
    SEMI_IMPLICIT_EULER("semi-implicit-euler", "semi-implicit Euler (shared, float)",
            "SIE (shared, float)", 1.0, 2.0),
    /**
     * Velocity Verlet as games write it: half kick, drift, forces at the half-kicked velocity,
     * half kick. Second order for forces of position only, first order once a force depends on
     * the velocity; stable to {@code 4m/b}.
     */
    VELOCITY_VERLET("velocity-verlet", "velocity Verlet (as games write it)",
            "Verlet (games)", 2.0, 4.0),
    /** The explicit midpoint method (a second-order Runge–Kutta method). */
    MIDPOINT("midpoint", "midpoint (RK2)", "midpoint", 2.0, 2.0),
    /** The classic fourth-order Runge–Kutta method. */
    RUNGE_KUTTA_4("rk4", "classic RK4", "RK4", 4.0, 2.785293563405282),
    /** The exact exponential step for gravity plus linear drag: no truncation error. */
    EXACT("exact", "exact step (gravity + linear drag)", "exact", Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY);

    private final String id;
    private final String label;
    private final String shortLabel;
    private final double order;
    private final double stabilityFactor;

    Scheme(String id, String label, String shortLabel, double order, double stabilityFactor) {
        this.id = id;
        this.label = label;
        this.shortLabel = shortLabel;
        this.order = order;
        this.stabilityFactor = stabilityFactor;
    }

    /**
     * Create a stepper of this scheme for a scene.
     *
     * @param forces the scene's forces (not null; {@link #EXACT} needs
     *     {@link ForceModel#hasClosedForm()})
     * @return a new stepper
     */
    public Stepper create(ForceModel forces) {
        switch (this) {
            case FORWARD_EULER:
                return new ForwardEuler(forces);
            case SEMI_IMPLICIT_EULER:
                return new SharedEulerStepper(forces);
            case VELOCITY_VERLET:
                return new VelocityVerlet(forces);
            case MIDPOINT:
                return new MidpointStepper(forces);
            case RUNGE_KUTTA_4:
                return new RungeKutta4(forces);
            case EXACT:
                return new ExactDragStep(forces);
            default:
                throw new AssertionError(this);
        }
    }

    /**
     * Test whether this scheme can step a scene.
     *
     * @param forces the scene's forces (not null)
     * @return false only for the exact step on a scene without a closed form
     */
    public boolean supports(ForceModel forces) {
        return this != EXACT || forces.hasClosedForm();
    }

    /**
     * Return the name used in CSV files and file names.
     *
     * @return e.g. {@code "rk4"}
     */
    public String id() {
        return id;
    }

    /**
     * Return the name used in plots and tables.
     *
     * @return e.g. {@code "classic RK4"}
     */
    public String label() {
        return label;
    }

    /**
     * Return a short name for chart legends.
     *
     * @return e.g. {@code "RK4"}
     */
    public String shortLabel() {
        return shortLabel;
    }

    /**
     * Return the theoretical order of the global error for a scene: the method's order, except
     * that with a constant acceleration (no velocity-dependent force) every method of order 2
     * or more is exact, and games' velocity Verlet drops to order 1 once a force depends on V.
     *
     * @param forces the scene's forces (not null)
     * @return the order p of {@code error ~ h^p}; infinite when exact up to round-off
     */
    public double theoreticalOrder(ForceModel forces) {
        if (order >= 2.0 && !forces.dependsOnVelocity()) {
            return Double.POSITIVE_INFINITY;
        }
        if (this == VELOCITY_VERLET) {
            return 1.0;
        }
        return order;
    }

    /**
     * Return the largest stable step under linear drag by theory: {@code factor·m/b}.
     *
     * @param linearRate k = b/m (in 1/s, &gt;0)
     * @return the limit (in seconds; infinite for the exact step)
     */
    public double theoryStableStep(double linearRate) {
        return stabilityFactor / linearRate;
    }

    /**
     * Return the stability factor: the step limit under linear drag in units of m/b.
     *
     * @return 2 for both Euler forms and the midpoint method, 4 for games' Verlet,
     *     2.785293563405282 for RK4, infinite for the exact step
     */
    public double stabilityFactor() {
        return stabilityFactor;
    }
}
