package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.aiming.Flight;
import particlelab.reference.SlideCode;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.MethodPart;
import particlelab.demo.WhatIfPart;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SlideFormDrag;
import particlelab.view.TextFormat;

/**
 * Demo 3, drag: three spheres launched together with the same {@code V0 = (10, 10, 0)} m/s and
 * mass {@code m = 1} kg. Builds upon gravitational pull; each sphere has its own integrator
 * holding its own forces:
 * <ol>
 * <li>gravity only (the parabola of demo 2);</li>
 * <li>gravity + linear drag {@code F = −b·V} with the lecture's {@code b = 0.9} N·s/m;</li>
 * <li>gravity + quadratic drag {@code F = −c·|V|·V}, or, switched with {@code law}, the
 * slide's {@code F = −c·|V|²·V} ({@link SlideFormDrag}: magnitude {@code c·|V|³}, not
 * physical; shown so students see why it is not used).</li>
 * </ol>
 *
 * <p>What to watch for: with drag the path is no longer a parabola: it climbs less, bends down
 * steeper and lands shorter. Linear drag pulls every velocity toward the terminal velocity
 * {@code m·g/b ≈ 10.9} m/s straight down; quadratic drag bites hardest at the start, when the
 * sphere is fastest. The HUD's stability line names the sphere whose stability limit is the
 * smallest at its current state ({@code 2m/b} for linear drag, {@code m/(c·|V|)} for quadratic
 * drag, which grows as the sphere slows); press T (raw tpf) and K (a long hitch, longer still
 * at a raised time scale) to see a long step pass a limit and the warning name the sphere.
 *
 * <p>The HUD's terminal speeds, closed forms beside the spheres' stepped speeds: linear
 * {@code v_t = m·g/b}, physical quadratic {@code √(m·g/c)}, slide form {@code (m·g/c)^(1/3)}
 * (where {@code c·v³ = m·g}); and the step limits there, {@code 2/λ} with {@code λ = n·g/v_t}
 * for a drag {@code ∝ vⁿ}: {@code 2v_t/g = 2m/b}, {@code v_t/g} and {@code 2v_t/(3g)}. The
 * Euler step's fixed point is where {@code a = 0}, so the stepped speed tends to the same v_t.
 *
 * <p>Bug hunt ({@code --set fault=slide-drag}): the third sphere runs the slide's
 * {@code −c·|V|²·V} while its label, equations and terminal speed still claim the physical
 * law, as a student who copied the slide would believe; {@code fault=random} hides it
 * ({@code --set seed=N}) until B reveals it, with where it lands against the physical law.
 *
 * <p>What if (Insert, Delete, J; {@link WhatIfPart}): a fork lane with h = 1/30 s, b = 2 N s/m,
 * the drag laws swapped ({@code --set drag=swapped}: the linear sphere runs quadratic drag with
 * {@code c' = m·g/v_t² = b²/(m·g)}, the quadratic sphere linear drag with
 * {@code b' = m·g/v_t}, so each keeps its terminal speed v_t and only the way there changes),
 * or another integration method ({@code --set method=euler}, {@link MethodPart}).
 */
public final class DragDemo extends DemoState {

    /** The lecture's linear drag coefficient b (N·s/m). */
    public static final float LINEAR_B = 0.9f;
    /** The quadratic drag coefficient c (kg/m), chosen to bite as hard as b at launch. */
    public static final float QUADRATIC_C = 0.064f;
    /** The common launch velocity (m/s). */
    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);
    private static final float MASS_KG = 1f;
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 30f;
    private static final float SPEED_STEP = 0.5f;
    /** The drag coefficients' largest values (N·s/m and kg/m). */
    private static final float MAX_B = 5f;
    private static final float MAX_C = 0.5f;
    /** The spheres' drawn radius (m). */
    private static final float SPHERE_RADIUS = 0.3f;
    /** The third sphere's drag laws, as {@code --set law=...} names them. */
    private static final String[] LAWS = {"physical", "slide"};
    /** The third sphere's labels, by law. */
    private static final String[] LAW_LABELS = {"quadratic drag  F = -c |V|V",
        "slide form  F = -c |V|²V (not physical)"};
    /** The swap of the drag laws: its parameter, its values, the spheres' labels then. */
    static final String SWAP = "drag";
    private static final String[] SWAPS = {"as-labelled", "swapped"};
    private static final String[] SWAPPED_LABELS = {"swapped: quadratic  F = -c' |V|V",
        "swapped: linear  F = -b' V"};
    /** The lane's note while the laws are swapped: it follows the labelled linear law. */
    private static final String LANE_SWAPPED_NOTE = "the lane, its exact path and the seen"
            + " errors follow the labelled law F = -b V, not the swapped one the sphere runs";
    /** The lens's notes: the step it re-takes is the recipe's, with the labelled law. */
    private static final String LENS_SWAPPED_NOTE = "not the sphere's step: the lens re-takes"
            + " the labelled law F = -b V, the sphere runs the swapped one (drag)";
    private static final String LENS_EULER_NOTE = "not the sphere's step: the lens re-takes"
            + " the lecture's recipe, the sphere steps by forward Euler (method)";
    private static final String LENS_BOTH_NOTE = "not the sphere's step: the lens re-takes"
            + " the labelled law by the recipe, the sphere the swapped one by forward Euler";
    /** The fault of this demo, by {@code --set fault=} name, and what it is. */
    static final String SLIDE_DRAG = "slide-drag";
    private static final String[] FAULTS = {SLIDE_DRAG};
    private static final String[] FAULT_TITLES = {"the slide's -c|V|²V as quadratic drag"};
    private static final String[] FAULT_LABELS = {"slide's |V|²V"};

    /** The launch, mass and g, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(LAUNCH_VELOCITY);
    private final LinearDrag linearDrag = new LinearDrag(LINEAR_B);
    /** The linear-drag sphere's gravity, which the lane's slide code reads too. */
    private final Gravity linearGravity = new Gravity();
    /** The comparison lane beside the linear-drag sphere (the report's closed-form case). */
    private final ComparisonLane lane = addPart(new ComparisonLane(
            () -> SlideCode.linearDrag(linearGravity, linearDrag), SPHERE_RADIUS));
    /** The derivative lens on the followed sphere (key O, {@code --set lens=on}). */
    private final LensPart lens = addPart(new LensPart(SPHERE_RADIUS));
    /** How the spheres step: the lecture's recipe, or forward Euler ({@code method}). */
    private final MethodPart method = addPart(new MethodPart());
    /**
     * What-if forks (Insert, Delete, J): as recorded, h = 1/30 s, b = 2 N s/m, the drag laws
     * swapped (v_t kept), forward Euler.
     */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(DragDemo::new,
            new String[] {null, "h", "b", SWAP, MethodPart.PARAMETER},
            new float[] {0f, 1f / 30f, 2f, 1f, MethodPart.FORWARD_EULER}, 0f));
    /** The swapped laws: quadratic drag on the linear sphere, linear on the quadratic one. */
    private final QuadraticDrag swappedQuadratic = new QuadraticDrag(0f);
    private final LinearDrag swappedLinear = new LinearDrag(0f);
    private ParticleIntegrator linearAsQuadratic;
    private ParticleIntegrator quadraticAsLinear;
    /** The drag laws are swapped ({@code --set drag=swapped}). */
    private boolean swapped;
    private DemoParticle linearSphere;
    private final QuadraticDrag quadraticDrag = new QuadraticDrag(QUADRATIC_C);
    /** The slide's form, on the same sphere: c is in one of the two, 0 in the other. */
    private final SlideFormDrag slideDrag = new SlideFormDrag(0f);
    /** The quadratic sphere's gravity, which the fault's flights read too. */
    private final Gravity quadraticGravity = new Gravity();
    /** The bug hunt's switch: the slide's form on the third sphere, unannounced. */
    private final FaultHunt faults = new FaultHunt(FAULTS, FAULT_TITLES, FAULT_LABELS);
    /** The consequence: the third sphere's landing x, slide form and physical (m). */
    private final FaultConsequence consequence = new FaultConsequence(faults, getClock(),
            "the third sphere", "the physical law");
    /** The law in the scene's label and equations: 0 physical, 1 the slide's form. */
    private int law;
    /** c as the parameter has it, for whichever law (kg/m or kg·s/m²). */
    private float coefficientC = QUADRATIC_C;
    private DemoParticle quadraticSphere;

    /** Create the demo. */
    public DragDemo() {
        super("Drag");
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
     * Return the closed-form terminal speed of a sphere's drag under the scene's g and mass:
     * {@code m·g/b} (linear), {@code √(m·g/c)} (physical quadratic) or {@code (m·g/c)^(1/3)} (the
     * slide's form, when chosen).
     *
     * @param index 1 for linear drag, 2 for the quadratic sphere (0 has no drag)
     * @return v_t (in m/s; infinite without drag)
     */
    public double terminalSpeed(int index) {
        double weight = getParticles().get(index).getParticle().getMass()
                * (double) getParameters().getValueInScene(getParameters().indexOf("g"));
        if (index == 1) {
            return weight / linearDrag.getCoefficient();
        }
        if (index != 2) {
            return Double.POSITIVE_INFINITY;
        }
        return law == 0 ? Math.sqrt(weight / coefficientC)
                : SlideFormDrag.terminalSpeed(1.0, weight, coefficientC);
    }

    /**
     * Tell whether the quadratic sphere runs the slide's form {@code −c·|V|²·V}.
     *
     * @return true for the slide's form, false for the physical {@code −c·|V|·V}
     */
    public boolean isSlideForm() {
        return law == 1;
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
        // Same launch for all three; only the forces differ.
        // The labels name the forces, not their numbers: the panel changes b and c.
        launch.add(addParticle("gravity only", ColorRGBA.Orange, Vector3f.ZERO,
                LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity())))).stopAtGround();
        linearSphere = launch.add(addParticle(linearLabel(),
                new ColorRGBA(0.3f, 0.85f, 1f, 1f), Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(linearGravity), linearDrag)));
        linearSphere.stopAtGround();
        // Both quadratic laws act on the third sphere, one of them with c = 0: adding a zero
        // force changes no bit of the physical law's step.
        quadraticSphere = launch.add(addParticle(quadraticLabel(),
                new ColorRGBA(1f, 0.4f, 0.8f, 1f), Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(quadraticGravity), quadraticDrag,
                        slideDrag)));
        quadraticSphere.stopAtGround();
        // The swapped laws, each with its sphere's gravity (g moves them too).
        linearAsQuadratic = new ParticleIntegrator(linearGravity, swappedQuadratic);
        quadraticAsLinear = new ParticleIntegrator(quadraticGravity, swappedLinear);
        for (int i = 0; i < 3; ++i) {
            method.drive(getParticles().get(i));
        }
        applySwap();
        QuadraticFlight faultyFlight = new QuadraticFlight();
        QuadraticFlight correctFlight = new QuadraticFlight();
        consequence.setFlight((fault, h) -> fault == 0 ? correctFlight.landingX(false, h)
                : faultyFlight.landingX(true, h));
        lane.follow(launch, linearSphere);
        lens.follow(linearSphere);
        setView(-2f, 24f, 7f, 1f, 5, SPHERE_RADIUS);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        launch.projectileParameters(MAX_SPEED, SPEED_STEP, MASS_KG).forEach(this::declareParameter);
        // The coefficients change the forces at once, in the middle of a flight.
        declareParameter(new DemoParameter("b", "linear drag", "N s/m", 0f, MAX_B,
                0.05f, LINEAR_B, 2, DemoParameter.Applies.LIVE, linearDrag::setCoefficient));
        declareParameter(new DemoParameter("c", "quadratic drag", "kg/m", 0f,
                MAX_C, 0.004f, QUADRATIC_C, 3, DemoParameter.Applies.LIVE, value -> {
                    coefficientC = value;
                    applyLaw();
                }));
        // The slide's −c|V|²V instead, from the next launch (with c in kg·s/m²).
        declareParameter(DemoParameter.choice("law", "quadratic law", LAWS, 0,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    int wanted = Math.round(value);
                    if (wanted != law) {
                        law = wanted;
                        lawChanged();
                    }
                }));
        // Each drag sphere runs the other law with its own v_t, from the next step on.
        declareParameter(DemoParameter.choice(SWAP, "drag laws", SWAPS, 0,
                DemoParameter.Applies.LIVE, value -> {
                    swapped = Math.round(value) == 1;
                    if (quadraticSphere != null) {
                        relabel(linearSphere, linearLabel());
                        relabel(quadraticSphere, quadraticLabel());
                        applySwap();
                    }
                }));
        declareParameter(faults.switchParameter(this::lawChanged));
        declareParameter(faults.seedParameter(this::lawChanged));
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

    /**
     * Tell whether the drag laws are swapped ({@code --set drag=swapped}).
     *
     * @return true if the linear sphere runs quadratic drag and the quadratic sphere linear
     */
    public boolean isSwapped() {
        return swapped;
    }

    /**
     * Access the integration method ({@code --set method=...}).
     *
     * @return the live part (not null)
     */
    public MethodPart getMethod() {
        return method;
    }

    /** The swapped laws' coefficients follow b, c, g and m: set before every step. */
    @Override
    protected void beforeStep(float stepSeconds) {
        applySwap();
    }

    /**
     * Give the swapped laws their coefficients, each keeping its sphere's v_t, and hand the
     * method part the forces each sphere runs with. Allocates nothing.
     */
    private void applySwap() {
        double weight = linearSphere.getParticle().getMass()
                * (double) getParameters().getValueInScene(getParameters().indexOf("g"));
        // quadratic with the linear sphere's v_t: m·g = c'·v_t², so c' = m·g/v_t² = b²/(m·g)
        double linear = terminalSpeed(1);
        float quadraticC = linear > 0.0 && linear < Double.POSITIVE_INFINITY
                ? (float) (weight / (linear * linear)) : 0f;
        // linear with the quadratic sphere's v_t: m·g = b'·v_t
        double quadratic = terminalSpeed(2);
        float linearB = quadratic > 0.0 && quadratic < Double.POSITIVE_INFINITY
                ? (float) (weight / quadratic) : 0f;
        if (swappedQuadratic.getCoefficient() != quadraticC) {
            swappedQuadratic.setCoefficient(quadraticC);
        }
        if (swappedLinear.getCoefficient() != linearB) {
            swappedLinear.setCoefficient(linearB);
        }
        method.setForces(linearSphere, swapped ? linearAsQuadratic
                : linearSphere.getIntegrator());
        method.setForces(quadraticSphere, swapped ? quadraticAsLinear
                : quadraticSphere.getIntegrator());
    }

    /**
     * Return the fault the third sphere runs now.
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
     * Access the fault's consequence: where the third sphere lands with the slide's form and
     * with the physical law, flown ahead from the launch as the world steps it.
     *
     * @return the live consequence (not null)
     */
    FaultConsequence getFaultConsequence() {
        return consequence;
    }
    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("a sphere"));
        declareDraggable(launch.dragVelocity("a sphere", getParameters()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        launch.appendLaunch(text.append("a = g + F/m,  "), getParameters());
        text.append(";   linear: F = -b V, b = ");
        DemoParameter.appendShort(text, linearDrag.getCoefficient(), 2).append(law == 0
                ? " N s/m;   quadratic (physical): F = -c |V| V, c = "
                : " N s/m;   slide form (not physical): F = -c |V|² V, c = ");
        DemoParameter.appendShort(text, coefficientC, 3).append(law == 0 ? " kg/m\n"
                : " kg s/m²\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        consequence.appendHudLine(text, "B");
        if (swapped) {
            DemoParameter.appendShort(text.append("Laws swapped (").append(SWAP)
                    .append("), v_t kept:  c' = b²/(mg) = "), swappedQuadratic.getCoefficient(),
                    3).append(" kg/m,  b' = mg/v_t = ");
            DemoParameter.appendShort(text, swappedLinear.getCoefficient(), 3)
                    .append(" N s/m\n");
        }
        // v_t from the closed forms (the spheres' lines give the stepped |V|), and the step's
        // limit 2/λ there.
        double g = getParameters().getValueInScene(getParameters().indexOf("g"));
        double weight = quadraticSphere.getParticle().getMass() * g;
        double linear = terminalSpeed(1);
        double physical = Math.sqrt(weight / coefficientC);
        double slide = SlideFormDrag.terminalSpeed(1.0, weight, coefficientC);
        // The forks' notes, set before the parts write their lines (they follow these): the
        // lane and the lens re-take the labelled law by the recipe, whatever the spheres run.
        lane.setForcesNote(swapped ? LANE_SWAPPED_NOTE : null);
        lens.setStepNote(method.getMethod() != MethodPart.RECIPE
                ? (swapped ? LENS_BOTH_NOTE : LENS_EULER_NOTE)
                : (swapped ? LENS_SWAPPED_NOTE : null));
        if (swapped) {
            // The laws each sphere runs now, each with its v_t kept: the linear sphere's
            // quadratic c' limits h to v_t/g there (λ = 2g/v_t), the quadratic sphere's
            // linear b' to 2v_t/g (λ = g/v_t).
            double quadraticVt = terminalSpeed(2);
            text.append("v_t (h < there), laws swapped: quadratic c' √(mg/c') ");
            TextFormat.appendFixed(text, linear, 2).append(" m/s (");
            TextFormat.appendFixed(text, linear / g, 3).append(" s), linear b' mg/b' ");
            TextFormat.appendFixed(text, quadraticVt, 2).append(" (");
            TextFormat.appendFixed(text, 2.0 * quadraticVt / g, 3).append(" s)\n");
            return;
        }
        text.append("v_t (h < there): mg/b ");
        TextFormat.appendFixed(text, linear, 2).append(" m/s (");
        TextFormat.appendFixed(text, 2.0 * linear / g, 3).append(" s), √(mg/c) ");
        TextFormat.appendFixed(text, physical, 2).append(" (");
        TextFormat.appendFixed(text, physical / g, 3).append(" s), slide (mg/c)^(1/3) ");
        TextFormat.appendFixed(text, slide, 2).append(" (");
        TextFormat.appendFixed(text, 2.0 * slide / (3.0 * g), 3).append(" s)\n");
    }

    /** Put c into the law that runs (the slide's form for law=slide or the fault) and 0 into
     * the other. */
    private void applyLaw() {
        boolean slideRuns = law == 1 || faults.active() != 0;
        quadraticDrag.setCoefficient(slideRuns ? 0f : coefficientC);
        slideDrag.setCoefficient(slideRuns ? coefficientC : 0f);
        consequence.markStale();
    }

    /** The law, the fault or the seed changed: the coefficients and the label. */
    private void lawChanged() {
        applyLaw();
        if (quadraticSphere != null) {
            relabel(quadraticSphere, quadraticLabel());
        }
    }

    /** @return the third sphere's label: its law, and the fault if one runs */
    private String quadraticLabel() {
        if (swapped) {
            return SWAPPED_LABELS[1];
        }
        return law == 1 ? LAW_LABELS[1] : faults.label(LAW_LABELS[0]);
    }

    /** @return the second sphere's label: linear drag, or the quadratic law swapped in */
    private String linearLabel() {
        return swapped ? SWAPPED_LABELS[0] : "linear drag  F = -b V";
    }

    /** Reveal the hidden fault (key B): the label and the HUD name it. */
    void revealFault() {
        if (faults.isHidden()) {
            faults.reveal();
            relabel(quadraticSphere, quadraticLabel());
        }
    }

    /**
     * The third sphere flown ahead from its launch with the same forces in the same order as
     * in the scene (so the same floats), c in the slide's form or the physical law. Allocates
     * nothing once made.
     */
    private final class QuadraticFlight {

        private final Particle ball = new Particle();
        private final QuadraticDrag physical = new QuadraticDrag(0f);
        private final SlideFormDrag slide = new SlideFormDrag(0f);
        private final Flight flight = new Flight(new ParticleIntegrator(quadraticGravity,
                physical, slide));

        /**
         * Fly the third sphere from its launch.
         *
         * @param slideForm true for the slide's {@code −c·|V|²·V}, false for the physical law
         * @param stepSeconds h (in seconds, &gt;0)
         * @return its landing x (in metres; NaN if it does not land)
         */
        double landingX(boolean slideForm, float stepSeconds) {
            physical.setCoefficient(slideForm ? 0f : coefficientC);
            slide.setCoefficient(slideForm ? coefficientC : 0f);
            ball.copyFrom(quadraticSphere.getParticle());
            quadraticSphere.copyLaunchPosition(ball.position);
            quadraticSphere.copyLaunchVelocity(ball.velocity);
            try {
                for (int n = 1; n <= FaultConsequence.MAX_FLIGHT_STEPS; ++n) {
                    double landing = flight.step(ball, stepSeconds);
                    if (landing != Flight.NO_LANDING) {
                        return flight.crossingX(landing);
                    }
                }
            } catch (NonFiniteStepException blowUp) {
                return Double.NaN;
            }
            return Double.NaN;
        }
    }

    /** The slide: the two drag laws with b/m and c/m; the three speeds (or landings). */
    @Override
    protected void writePresentation(Presentation slide) {
        java.util.List<particlelab.demo.DemoParticle> balls = getParticles();
        float mass = balls.get(1).getParticle().getMass();
        particlelab.view.TextFormat.appendFixed(slide.formula()
                .append("linear:  a = g - (b/m)V,   b/m = "),
                linearDrag.getCoefficient() / mass, 2).append(" /s");
        particlelab.view.TextFormat.appendFixed(slide.formula()
                .append(law == 0 ? "quadratic:  a = g - (c/m)|V|V,   c/m = "
                        : "slide form (not physical):  a = g - (c/m)|V|²V,   c/m = "),
                coefficientC / mass, 3).append(" /m");
        StringBuilder readout = slide.readout().append("gravity only ");
        Presentation.appendSpeedOrLanding(readout, balls.get(0)).append(",  linear ");
        Presentation.appendSpeedOrLanding(readout, balls.get(1)).append(",  quadratic ");
        Presentation.appendSpeedOrLanding(readout, balls.get(2));
    }
}
