package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.aiming.Flight;
import particlelab.reference.SlideCode;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.WhatIfPart;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Thrust;
import particlelab.view.TextFormat;

/**
 * Demo 4, thrust: two spheres launched together with {@code V0 = (10, 10, 0)} m/s: pull + drag
 * (the linear-drag sphere of demo 3), and pull + drag + thrust {@code F = k·V/|V|} with
 * {@code k = 2} N along the sphere's <em>own</em> velocity. Builds upon the drag demo.
 *
 * <p>The original lecture code pushed one sphere along the other sphere's velocity; here each
 * motor pushes where its own sphere flies. What to watch for: the thruster keeps its speed
 * longer and flies farther, and its thrust turns with it as gravity bends the path down.
 * Without gravity it would settle at the terminal speed {@code k/b ≈ 2.2} m/s.
 *
 * <p>Bug hunt ({@code --set fault=...}, {@link LectureFaults}): {@code other-velocity} pushes
 * the thruster along the other sphere's velocity, as the original listing did;
 * {@code unnormalised} pushes with {@code k·V} (the direction never normalised);
 * {@code random} picks one ({@code --set seed=N}) and hides which until B reveals it, with
 * where the faulty code lands against the correct one.
 */
public final class ThrustDemo extends DemoState {

    /** The lecture's thrust (N). */
    public static final float THRUST_K = 2f;
    /** The lecture's linear drag coefficient b (N·s/m). */
    public static final float LINEAR_B = 0.9f;
    /** The common launch velocity (m/s). */
    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);
    private static final float MASS_KG = 1f;
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 30f;
    private static final float SPEED_STEP = 0.5f;
    /** The largest drag coefficient (N·s/m) and thrust (N) offered. */
    private static final float MAX_B = 5f;
    private static final float MAX_K = 20f;
    /** The spheres' drawn radius (m). */
    private static final float SPHERE_RADIUS = 0.18f;
    /** The thruster's label, without a fault. */
    private static final String THRUSTER_LABEL = "pull + drag + thrust k";
    /** The faults of this demo, by {@code --set fault=} name, and what each one is. */
    static final String OTHER_VELOCITY = "other-velocity";
    static final String UNNORMALISED = "unnormalised";
    private static final String[] FAULTS = {OTHER_VELOCITY, UNNORMALISED};
    private static final String[] FAULT_TITLES = {"thrust along the other sphere's velocity",
        "thrust direction not normalised (F = k V)"};
    private static final String[] FAULT_LABELS = {"other sphere's V", "k V unnormalised"};

    /** The launch, mass and g, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(LAUNCH_VELOCITY);
    /** Both spheres feel the same drag; only the second one thrusts. */
    private final LinearDrag drag = new LinearDrag(LINEAR_B);
    private final LinearDrag thrusterDrag = new LinearDrag(LINEAR_B);
    private final Thrust thrust = new Thrust(THRUST_K);
    /** The thruster's gravity, which the lane's slide code reads too. */
    private final Gravity thrusterGravity = new Gravity();
    /** The comparison lane beside the thruster. */
    private final ComparisonLane lane = addPart(new ComparisonLane(
            () -> SlideCode.thrust(thrusterGravity, thrusterDrag, thrust), SPHERE_RADIUS));
    /** The derivative lens on the followed sphere (key O, {@code --set lens=on}). */
    private final LensPart lens = addPart(new LensPart(SPHERE_RADIUS));
    /** What-if forks (Insert, Delete, J): as recorded, h = 1/30 s, b = 2 N s/m. */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(ThrustDemo::new,
            new String[] {null, "h", "b"}, new float[] {0f, 1f / 30f, 2f}, 0f));
    /** The bug hunt's switch; k goes to the thrust the switch names (one of these three). */
    private final FaultHunt faults = new FaultHunt(FAULTS, FAULT_TITLES, FAULT_LABELS);
    /** The faulty thrusts, beside the correct one in the thruster's integrator. */
    private LectureFaults.ThrustAlongAnother alongOther;
    private final LectureFaults.UnnormalisedThrust unnormalised =
            new LectureFaults.UnnormalisedThrust();
    /** k as the parameter has it (N), for whichever thrust runs. */
    private float thrustK = THRUST_K;
    /** The fault's consequence: the thruster's landing x, faulty and correct (m; NaN: none). */
    private final FaultConsequence consequence = new FaultConsequence(faults, getClock(),
            "the thruster", "the correct code");
    /** Scratch: the thruster's launch velocity (m/s). */
    private final Vector3f launchScratch = new Vector3f();
    private DemoParticle pullDragSphere;
    private DemoParticle thruster;

    /** Create the demo. */
    public ThrustDemo() {
        super("Thrust");
    }

    /**
     * Access the comparison lane ({@code --set lane=...}, key L).
     *
     * @return the live lane (not null)
     */
    public ComparisonLane getLane() {
        return lane;
    }

    /**
     * Access the derivative lens ({@code --set lens=on}, key O).
     *
     * @return the live lens part (not null)
     */
    public LensPart getLens() {
        return lens;
    }

    /**
     * Access the what-if forks (Insert, Delete, J).
     *
     * @return the live part (not null)
     */
    public WhatIfPart getWhatIf() {
        return whatIf;
    }

    @Override
    protected void createScene() {
        launch.add(addParticle("pull + drag", new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity()), drag))).stopAtGround();
        pullDragSphere = getParticles().get(0);
        // The faulty thrusts sit beside the correct one, at k = 0 while off: they add nothing.
        alongOther = new LectureFaults.ThrustAlongAnother(pullDragSphere.getParticle());
        thruster = launch.add(addParticle(faults.label(THRUSTER_LABEL),
                new ColorRGBA(1f, 0.75f, 0.2f, 1f), Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(thrusterGravity), thrusterDrag, thrust,
                        alongOther, unnormalised)));
        thruster.stopAtGround();
        // The pair flown ahead for a fault's consequence, faulty and correct.
        ThrusterFlight faultyFlight = new ThrusterFlight();
        ThrusterFlight correctFlight = new ThrusterFlight();
        consequence.setFlight(new FaultConsequence.AheadFlight() {
            @Override
            public double landingX(int fault, float stepSeconds) {
                return (fault == 0 ? correctFlight : faultyFlight).landingX(fault, stepSeconds);
            }

            @Override
            public void appendBefore(StringBuilder text, int fault) {
                if (fault == 2) {
                    // F = k·V: at launch its magnitude is k·|V0|, not k
                    float launchSpeed = thruster.copyLaunchVelocity(launchScratch).length();
                    TextFormat.appendFixed(text.append("pushes k|V| = "),
                            thrustK * launchSpeed, 2).append(" N at launch, not k = ");
                    TextFormat.appendFixed(text, thrustK, 2).append(" N; ");
                }
            }
        });
        applyFault();
        lane.follow(launch, thruster);
        lens.follow(thruster);
        setView(-1f, 14f, 4.5f, 0.5f, 4, SPHERE_RADIUS);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        launch.projectileParameters(MAX_SPEED, SPEED_STEP, MASS_KG).forEach(this::declareParameter);
        declareParameter(new DemoParameter("b", "linear drag", "N s/m", 0f, MAX_B,
                0.05f, LINEAR_B, 2, DemoParameter.Applies.LIVE, value -> {
                    drag.setCoefficient(value);
                    thrusterDrag.setCoefficient(value);
                    consequence.markStale();
                }));
        declareParameter(new DemoParameter("k", "thrust", "N", 0f, MAX_K, 0.25f,
                THRUST_K, 2, DemoParameter.Applies.LIVE, value -> {
                    thrustK = value;
                    applyFault();
                }));
        declareParameter(faults.switchParameter(this::faultChanged));
        declareParameter(faults.seedParameter(this::faultChanged));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_B, "B", FaultHunt.REVEAL_DESCRIPTION,
                this::revealFault);
    }

    @Override
    protected void onRestart() {
        consequence.markStale();
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        consequence.appendHudLine(text, "B");
    }

    /**
     * Return the fault the thruster runs now.
     *
     * @return its {@code --set fault=} name, or "none"
     */
    public String getActiveFault() {
        return faults.activeName();
    }

    /**
     * Return the seed of "spot the fault" ({@code --set seed=N}), as its pick uses it.
     *
     * @return the seed
     */
    public float getFaultSeed() {
        return faults.getSeed();
    }

    /**
     * Access the fault's consequence: where the thruster lands with the faulty code that runs
     * and with the correct code, flown ahead from the launch exactly as the world steps it.
     *
     * @return the live consequence (not null)
     */
    FaultConsequence getFaultConsequence() {
        return consequence;
    }

    /** Reveal the hidden fault (key B): the label and the HUD name it. */
    void revealFault() {
        if (faults.isHidden()) {
            faults.reveal();
            relabel(thruster, faults.label(THRUSTER_LABEL));
        }
    }

    /** The switch or the seed changed: the coefficients, the label, the consequence. */
    private void faultChanged() {
        applyFault();
        if (thruster != null) {
            relabel(thruster, faults.label(THRUSTER_LABEL));
        }
    }

    /** Put k into the thrust the switch names and 0 into the other two. */
    private void applyFault() {
        int fault = faults.active();
        thrust.setMagnitude(fault == 0 ? thrustK : 0f);
        if (alongOther != null) {
            alongOther.setMagnitude(fault == 1 ? thrustK : 0f);
        }
        unnormalised.setMagnitude(fault == 2 ? thrustK : 0f);
        consequence.markStale();
    }

    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("a sphere"));
        declareDraggable(launch.dragVelocity("a sphere", getParameters()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        launch.appendLaunch(text.append("a = g + F/m,  "), getParameters()).append('\n');
        text.append("drag F = -b V, b = ");
        DemoParameter.appendShort(text, drag.getCoefficient(), 2).append(" N s/m;   thrust"
                + " F = k V/|V|, k = ");
        DemoParameter.appendShort(text, thrustK, 2)
                .append(" N along the sphere's OWN velocity\n");
    }

    /** The slide: thrust along its own velocity against drag; both speeds (or landings). */
    @Override
    protected void writePresentation(Presentation slide) {
        StringBuilder formula = slide.formula().append("a = g - (b/m)V + (k/m)V/|V|,   b = ");
        DemoParameter.appendShort(formula, drag.getCoefficient(), 2).append(" N s/m,  k = ");
        DemoParameter.appendShort(formula, thrustK, 2).append(" N");
        List<DemoParticle> spheres = getParticles();
        StringBuilder readout = slide.readout().append("pull + drag ");
        Presentation.appendSpeedOrLanding(readout, spheres.get(0)).append(",  with thrust ");
        Presentation.appendSpeedOrLanding(readout, spheres.get(1));
    }

    /**
     * The pair flown ahead from the launch, as the world steps it: the pull + drag sphere
     * first, then the thruster with the same forces in the same order as in the scene (so
     * the same floats), each stopped where it comes down through the ground (its velocity
     * then 0, as the world's stick leaves it). Allocates nothing once made.
     */
    private final class ThrusterFlight {

        private final Particle other = new Particle();
        private final Particle ship = new Particle();
        private final Thrust correct = new Thrust(0f);
        private final LectureFaults.ThrustAlongAnother faultyAlong =
                new LectureFaults.ThrustAlongAnother(other);
        private final LectureFaults.UnnormalisedThrust faultyUnnormalised =
                new LectureFaults.UnnormalisedThrust();
        private final Flight otherFlight = new Flight(pullDragSphere.getIntegrator());
        private final Flight shipFlight = new Flight(new ParticleIntegrator(thrusterGravity,
                thrusterDrag, correct, faultyAlong, faultyUnnormalised));

        /**
         * Fly the pair from the thruster's launch.
         *
         * @param fault 0 for the correct thrust, else the fault's number
         * @param stepSeconds h (in seconds, &gt;0)
         * @return the thruster's landing x (in metres; NaN if it does not land)
         */
        double landingX(int fault, float stepSeconds) {
            correct.setMagnitude(fault == 0 ? thrustK : 0f);
            faultyAlong.setMagnitude(fault == 1 ? thrustK : 0f);
            faultyUnnormalised.setMagnitude(fault == 2 ? thrustK : 0f);
            other.copyFrom(pullDragSphere.getParticle());
            pullDragSphere.copyLaunchPosition(other.position);
            pullDragSphere.copyLaunchVelocity(other.velocity);
            ship.copyFrom(thruster.getParticle());
            thruster.copyLaunchPosition(ship.position);
            thruster.copyLaunchVelocity(ship.velocity);
            boolean otherFlies = true;
            try {
                for (int n = 1; n <= FaultConsequence.MAX_FLIGHT_STEPS; ++n) {
                    double otherLanding = Flight.NO_LANDING;
                    if (otherFlies) {
                        otherLanding = otherFlight.step(other, stepSeconds);
                    }
                    double shipLanding = shipFlight.step(ship, stepSeconds);
                    if (shipLanding != Flight.NO_LANDING) {
                        return shipFlight.crossingX(shipLanding);
                    }
                    if (otherLanding != Flight.NO_LANDING) {
                        otherFlies = false;
                        other.velocity.zero();
                    }
                }
            } catch (NonFiniteStepException blowUp) {
                return Double.NaN;
            }
            return Double.NaN;
        }
    }
}
