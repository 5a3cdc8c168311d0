package particlelab.accuracy;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;


/**
 * One of the report's canonical scenes: the forces, the launch and how long to fly. All start
 * from the origin at (20, 30) m/s under g = 9.8 m/s² on 1 kg, as the reference table of
 * docs/numerics.md.
 */
public final class CanonicalCase {

    /** The pull of gravity of every case (in m/s²). */
    public static final double G = 9.8;
    /** How long every case flies (in seconds): a whole number of steps for h = 1/15·2^-n. */
    public static final double DURATION_SECONDS = 4.0;

    private static final List<CanonicalCase> ALL = Collections.unmodifiableList(Arrays.asList(
            new CanonicalCase("gravity", "gravity only", ForceModel.perUnitMass(G, 0, 0, 0)),
            new CanonicalCase("drag-0.1", "linear drag b/m = 0.1 /s",
                    ForceModel.perUnitMass(G, 0.1, 0, 0)),
            new CanonicalCase("drag-0.5", "linear drag b/m = 0.5 /s",
                    ForceModel.perUnitMass(G, 0.5, 0, 0)),
            new CanonicalCase("drag-2", "linear drag b/m = 2 /s",
                    ForceModel.perUnitMass(G, 2.0, 0, 0)),
            new CanonicalCase("quadratic", "quadratic drag c/m = 0.01 /m",
                    ForceModel.perUnitMass(G, 0, 0.01, 0)),
            new CanonicalCase("thrust-drag", "thrust T/m = 5 m/s² + linear drag b/m = 0.5 /s",
                    ForceModel.perUnitMass(G, 0.5, 0, 5.0))));

    private final String id;
    private final String label;
    private final ForceModel forces;

    private CanonicalCase(String id, String label, ForceModel forces) {
        this.id = id;
        this.label = label;
        this.forces = forces;
    }

    /**
     * List the canonical cases in report order.
     *
     * @return an unmodifiable list
     */
    public static List<CanonicalCase> all() {
        return ALL;
    }

    /**
     * Return the launch state: the origin, V = (20, 30, 0) m/s.
     *
     * @return a new state
     */
    public static MotionState launch() {
        return new MotionState(0.0, 0.0, 20.0, 30.0);
    }

    /**
     * Return the name used in CSV and file names.
     *
     * @return e.g. {@code "drag-0.5"}
     */
    public String id() {
        return id;
    }

    /**
     * Return the name used in plots and tables.
     *
     * @return e.g. {@code "linear drag b/m = 0.5 /s"}
     */
    public String label() {
        return label;
    }

    /**
     * Return the forces.
     *
     * @return the model (immutable)
     */
    public ForceModel forces() {
        return forces;
    }

    /**
     * Tell how the reference is obtained.
     *
     * @return "closed form" or "RK4 at h = 1/30720 s"
     */
    public String referenceKind() {
        return forces.hasClosedForm() ? "closed form"
                : "RK4 at h = 1/" + ClosedForms.REFERENCE_STEPS_PER_SECOND + " s";
    }
}
