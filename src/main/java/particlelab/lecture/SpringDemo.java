package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Spring;
import particlelab.view.CurveView;
import particlelab.view.TextFormat;

/**
 * Demo 18, spring pull: the last force of the lecture's "simulation recipe" (gravity, drag,
 * thrust, spring pull). Two masses of {@code m = 1} kg are pulled toward their anchors A by
 * springs of rest length 0, started {@value #PULL_METRES} m below them at rest; one spring is
 * undamped, the other has a dashpot. Builds upon gravitational pull: the step is the same
 * {@code a = g + F/m}, {@code V += h·a}, {@code P += h·V}, with one more force, the recipe's
 * spring pull {@code F = −k·(P − A) − c·V} ({@link Spring} of rest length 0, whose damping acts
 * along the spring: on the vertical line through A, where these masses move, that is this
 * force exactly, and linear everywhere, so the closed form below holds at every h).
 *
 * <p>The exact motion about the rest height {@code y_eq = A_y − m·g/k} (gravity only shifts
 * it), with {@code ω = √(k/m)}, {@code λ = c/m}, {@code ω_d = √(ω² − λ²/4)} and the start
 * {@code A = y0 − y_eq} at rest: undamped {@code y − y_eq = A·cos ωt}, damped
 * {@code y − y_eq = A·e^(−λt/2)·(cos ω_d·t + λ/(2ω_d)·sin ω_d·t)} (the parameters' ranges keep
 * {@code λ/2 < ω}: always underdamped). The HUD writes it beside the stepped height, and each
 * mass's exact ghost moves with it.
 *
 * <p>What to watch for: the stability limit on the HUD, {@code h < 2/ω} undamped and
 * {@code h < 4/(λ + √(λ² + 4ω²))} damped (docs/numerics.md, "The damped oscillator"): with the
 * default {@code k = 144} N/m, {@code ω = 12} /s, these are 0.167 s and 0.153 s. At
 * {@code h = 1/10} s both still swing (the undamped one with its amplitude bounded, not kept:
 * the step keeps a modified energy); push h to 1/5 s on the panel (F2) and the warning names
 * the mass whose limit it passed, the swing grows every step and the demo resets once it blows
 * up. Between the two limits ({@code --set h=0.16}) only the damped spring is unstable:
 * damping lowers the limit of this step.
 */
public final class SpringDemo extends DemoState {

    /** The springs' default constant k (N/m): ω = 12 /s, 2/ω = 0.167 s. */
    public static final float SPRING_K = 144f;
    /** The damped spring's default damping c (N·s/m): λ = 2 /s. */
    public static final float DAMPING_C = 2f;
    /** How far below its anchor each mass starts, at rest (m). */
    public static final float PULL_METRES = 3f;
    /** The anchors' height (m). */
    public static final float ANCHOR_Y = 6.5f;
    /** Each mass (kg): ω² = k/m. */
    public static final float MASS_KG = 1f;
    /** Where the masses start, at rest (m). */
    private static final float START_Y = ANCHOR_Y - PULL_METRES;
    /** Where the two springs hang (m). */
    private static final float UNDAMPED_X = 3f;
    private static final float DAMPED_X = 7f;
    /** The k the panel's keys step through: squares, so ω is a whole number (N/m). */
    private static final float[] K_STOPS = {25f, 36f, 64f, 100f, 144f, 196f, 256f, 400f};
    /** The damping's largest value (N·s/m): λ/2 = 2.5 /s stays below the smallest ω, 5 /s. */
    private static final float MAX_C = 5f;
    /** Zigzag corners of a drawn spring, and its width and drawn half-width (m). */
    private static final int COIL_POINTS = 26;
    private static final float COIL_HALF_WIDTH = 0.45f;
    private static final float COIL_LINE_METRES = 0.09f;

    private final Gravity gravity = new Gravity();
    private final Spring undampedSpring = new Spring(new Vector3f(UNDAMPED_X, ANCHOR_Y, 0f),
            0f, SPRING_K);
    private final Spring dampedSpring = new Spring(new Vector3f(DAMPED_X, ANCHOR_Y, 0f),
            0f, SPRING_K, DAMPING_C);
    private final Spring[] springs = {undampedSpring, dampedSpring};
    private final DemoParticle[] masses = new DemoParticle[2];
    private final CurveView[] coils = new CurveView[2];
    /** Scratch for the coils' corners (m). */
    private final float[] coilXs = new float[COIL_POINTS];
    private final float[] coilYs = new float[COIL_POINTS];
    /** Scratch: an anchor (m). */
    private final Vector3f anchor = new Vector3f();

    /** Create the demo. */
    public SpringDemo() {
        super("Spring pull");
        // The slide is about energy: presenting shows the ledger's bars.
        getEnergyPart().showOnSlide();
    }

    // ------------------------------------------------------------------ public API ----

    /**
     * Return the exact height of a mass at a time since its release, from the closed form
     * in the class comment, with the spring's k and c as they are now.
     *
     * @param index 0 for the undamped mass, 1 for the damped one
     * @param seconds t since the release (in seconds, &ge;0)
     * @return y (in metres)
     */
    public double exactHeight(int index, double seconds) {
        Spring spring = springs[index];
        double omegaSquared = (double) spring.getSpringConstant() / MASS_KG;
        double lambda = (double) spring.getDamping() / MASS_KG;
        double rest = ANCHOR_Y - (double) MASS_KG * Gravity.STANDARD_G
                / (double) spring.getSpringConstant();
        double start = START_Y - rest;
        double damped = Math.sqrt(omegaSquared - 0.25 * lambda * lambda);
        double phase = damped * seconds;
        return rest + start * Math.exp(-0.5 * lambda * seconds)
                * (Math.cos(phase) + 0.5 * lambda / damped * Math.sin(phase));
    }

    /**
     * Return the stability limit of a mass's step, as the HUD shows it: the damped
     * oscillator's {@code 4/(λ + √(λ² + 4ω²))} with {@code λ = c/m} and {@code ω² = k/m}
     * ({@link ParticleIntegrator#stableStepLimit}), which is {@code 2/ω} without damping.
     *
     * @param index 0 for the undamped mass, 1 for the damped one
     * @return the largest stable h (in seconds)
     */
    public float stableStepLimit(int index) {
        DemoParticle mass = getParticles().get(index);
        return mass.getIntegrator().maxStableStep(mass.getParticle());
    }

    // ------------------------------------------------------------ framework hooks ----

    @Override
    protected void createScene() {
        // The recipe's forces, summed: gravity, and the spring pull F = −k·(P − A) − c·V.
        masses[0] = addParticle("undamped spring",
                new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                new Vector3f(UNDAMPED_X, START_Y, 0f), Vector3f.ZERO, MASS_KG,
                new ParticleIntegrator(gravity, undampedSpring));
        masses[1] = addParticle("damped spring",
                new ColorRGBA(1f, 0.6f, 0.2f, 1f),
                new Vector3f(DAMPED_X, START_Y, 0f), Vector3f.ZERO, MASS_KG,
                new ParticleIntegrator(gravity, dampedSpring));
        // The masses never land: their records get the whole cap now, not by doubling later
        // (the frame allocates nothing).
        for (DemoParticle mass : masses) {
            mass.getRecord().reserveAll();
        }
        setView(-2f, 12f, 2f * ANCHOR_Y - START_Y + 0.5f, 1f, 5, 0.3f);
        showExactGhosts();
        // |V| reaches ω·A, about 24 m/s: its arrow would cross the scene and the text (V
        // shows it).
        hideArrowsAtStart();
    }

    @Override
    protected void declareParameters() {
        // k and c start the masses again from their pull (R), so the closed form holds.
        declareParameter(new DemoParameter("k", "spring constant", "N/m", K_STOPS[0],
                K_STOPS[K_STOPS.length - 1], 1f, SPRING_K, 0,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    undampedSpring.setSpringConstant(value);
                    dampedSpring.setSpringConstant(value);
                }).withStops(K_STOPS));
        declareParameter(new DemoParameter("c", "damping (orange)", "N s/m", 0f, MAX_C, 0.5f,
                DAMPING_C, 1, DemoParameter.Applies.NEXT_LAUNCH, dampedSpring::setDamping));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("Spring pull:  a = g + F/m,  F = -k·(P - A) - c·V,  k = ");
        DemoParameter.appendShort(text, undampedSpring.getSpringConstant(), 1)
                .append(" N/m,  m = 1 kg,  c = 0 (blue) and ");
        DemoParameter.appendShort(text, dampedSpring.getDamping(), 2).append(" N s/m (orange)\n");
        text.append("Exact y - y_eq (y_eq = A_y - m·g/k):  A·cos ωt;  damped"
                + " A·e^(-λt/2)·(cos ω_d t + λ/(2ω_d)·sin ω_d t)\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        double omega = Math.sqrt(undampedSpring.getSpringConstant() / MASS_KG);
        text.append("Limits (ω = ");
        TextFormat.appendFixed(text, omega, 2).append(" /s, λ = ");
        TextFormat.appendFixed(text, dampedSpring.getDamping() / MASS_KG, 2)
                .append(" /s):  undamped h < 2/ω = ");
        TextFormat.appendFixed(text, stableStepLimit(0), 3).append(" s,  damped h < 4/(λ +"
                + " √(λ² + 4ω²)) = ");
        TextFormat.appendFixed(text, stableStepLimit(1), 3).append(" s;  h = ");
        DemoParameter.appendStep(text, getClock().getStepSeconds()).append('\n');
        double t = getClock().getSimulatedSeconds();
        text.append("Height y, Euler | exact:  undamped ");
        TextFormat.appendFixed(text, masses[0].getParticle().position.y, 3).append(" | ");
        TextFormat.appendFixed(text, exactHeight(0, t), 3).append(" m,  damped ");
        TextFormat.appendFixed(text, masses[1].getParticle().position.y, 3).append(" | ");
        TextFormat.appendFixed(text, exactHeight(1, t), 3).append(" m\n");
    }

    @Override
    protected void afterFrame() {
        for (int i = 0; i < coils.length; ++i) {
            if (coils[i] != null) {
                drawCoil(i);
            }
        }
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        for (int i = 0; i < coils.length; ++i) {
            coils[i] = new CurveView(app.getAssetManager(), "spring " + i, COIL_POINTS,
                    COIL_LINE_METRES, new ColorRGBA(0.85f, 0.85f, 0.85f, 1f));
            getSceneNode().attachChild(coils[i].getGeometry());
            drawCoil(i);
        }
    }

    // ------------------------------------------------------------ private helpers ----

    /**
     * Draw a spring as a zigzag from its anchor (marked by a short bar) to its mass, above
     * or below it. Allocates nothing.
     */
    private void drawCoil(int index) {
        springs[index].copyAnchor(anchor);
        Vector3f mass = masses[index].getParticle().position;
        coilXs[0] = anchor.x - 2f * COIL_HALF_WIDTH;
        coilYs[0] = anchor.y;
        coilXs[1] = anchor.x + 2f * COIL_HALF_WIDTH;
        coilYs[1] = anchor.y;
        coilXs[2] = anchor.x;
        coilYs[2] = anchor.y;
        int corners = COIL_POINTS - 4;
        for (int n = 0; n <= corners; ++n) {
            float along = (float) n / corners;
            float side = n == 0 || n == corners ? 0f
                    : (n % 2 == 0 ? COIL_HALF_WIDTH : -COIL_HALF_WIDTH);
            coilXs[3 + n] = mass.x + side;
            coilYs[3 + n] = anchor.y + along * (mass.y - anchor.y);
        }
        coils[index].setPoints(coilXs, coilYs, COIL_POINTS);
    }

    /** The slide: the spring pull and its step limits; each mass's height against exact. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        StringBuilder formula = slide.formula().append("a = g + F/m,  F = -k(P - A) - cV,  k = ");
        DemoParameter.appendShort(formula, undampedSpring.getSpringConstant(), 1)
                .append(" N/m");
        formula = slide.formula().append("stable while h < 2/ω = ");
        TextFormat.appendFixed(formula, stableStepLimit(0), 3).append(" s (damped ");
        TextFormat.appendFixed(formula, stableStepLimit(1), 3).append(" s),  h = ");
        DemoParameter.appendStep(formula, getClock().getStepSeconds());
        double t = getClock().getSimulatedSeconds();
        StringBuilder readout = slide.readout().append("y Euler | exact:  ");
        TextFormat.appendFixed(readout, masses[0].getParticle().position.y, 3).append(" | ");
        TextFormat.appendFixed(readout, exactHeight(0, t), 3).append(" m,  damped ");
        TextFormat.appendFixed(readout, masses[1].getParticle().position.y, 3).append(" | ");
        TextFormat.appendFixed(readout, exactHeight(1, t), 3).append(" m");
    }
}
