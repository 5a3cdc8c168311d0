package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Node;
import particlelab.physics.DerivativeLens;
import particlelab.physics.Particle;
import particlelab.reference.ExactPath;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.LensGraph;
import particlelab.view.ScreenRect;
import particlelab.view.StepDotPick;
import particlelab.view.TextFormat;
import particlelab.view.VelocityArrow;
import particlelab.world.StateRing;

/**
 * The derivative lens on screen (issue 32 §2), a part of the free-flight demos: key O (or
 * {@code --set lens=on}) looks closely at one step of the followed sphere and draws, as
 * arrows from {@code P_i}, the chord {@code (P_{i+1} − P_i)/h}, the velocity the step used
 * ({@code V_{i+1}} for the lecture's step), and the exact tangents {@code dP/dt} at
 * {@code t_i} and at the step's middle {@code t_i + h/2}; one HUD line each gives its value,
 * named by its arrow's colour. The values are {@link DerivativeLens}'s.
 *
 * <p>Which step: the one that starts where the sphere is shown. Replaying (the ring's Home
 * and End) that is the shown entry's step to the next entry; at the live end, the step the
 * sphere is about to take from where it is now, of the clock's h (in raw-tpf mode the last
 * step's length). The step is taken again
 * on a copy with the sphere's own integrator (the same float operations, so the same bits as
 * the world's step in free flight); the exact tangents come from the sphere's
 * {@link ExactPath} started at {@code (P_i, V_i)}: at {@code t_i} that is {@code V_i}
 * itself, at the middle the path's velocity after h/2.
 *
 * <p>Clicking a step dot of the sphere's trail chooses that step: the demo shows it, as Home
 * and End would (paused, the later steps kept for End until Space or N go on), and the lens
 * looks at it. The nearest dot within {@link DragControl#MIN_PICK_PIXELS} of the press, of
 * the steps the replay ring holds, is taken ({@link StepDotPick}); a press on a grip or a
 * sphere is theirs first.
 *
 * <p>Beside the scene, in the strip down its right edge (below the energy bars when they are
 * shown, so no body flies under it), a {@link LensGraph} plots V_x and V_y of the steps up to
 * the chosen one and of the step looked at against t, the chosen step marked, with the slope
 * of each curve there computed from those two plotted points ({@link LensSteps}): the
 * acceleration the step applied, {@code −g} for V_y under gravity alone.
 *
 * <p>Under gravity the chord is {@code V_{i+1}} bit for bit, and the tangents are
 * {@code g·h} and {@code g·h/2} away from it: the arrows nearly coincide at the lecture's h,
 * the HUD's numbers tell them apart. Presenting, one formula line gives their y components.
 * Its frame hook, HUD lines and slide line allocate nothing.
 */
public final class LensPart implements DemoPart {

    /** The parameter's name ({@code --set lens=on}). */
    public static final String PARAMETER = "lens";
    /** The key that switches the lens on and off. */
    public static final int KEY = KeyInput.KEY_O;
    /**
     * How many seconds of travel an arrow's length stands for: longer than the sphere's own
     * velocity arrow (0.4 s), so the lens's arrows reach past it.
     */
    private static final float ARROW_SECONDS = 1f;
    /** Decimals of the values: 3, so that g·h/2 = 0.082 m/s at h = 1/60 s shows. */
    private static final int DECIMALS = 3;
    /** The arrows' colours, in {@link #CHORD}, {@link #STEP}, ... order. */
    private static final ColorRGBA[] COLORS = {ColorRGBA.Yellow, ColorRGBA.White,
        new ColorRGBA(1f, 0.55f, 0.1f, 1f), ColorRGBA.Green};
    /** The colours' names as the HUD lines give them. */
    private static final String[] COLOR_NAMES = {"yellow", "white", "orange", "green"};
    /**
     * The arrows' shaft widths, as fractions of the sphere's radius: widest first, so that
     * arrows that coincide (the chord and V_{i+1}) still show each other's edges.
     */
    private static final float[] WIDTHS = {0.9f, 0.5f, 0.3f, 0.15f};
    private static final int CHORD = 0;
    private static final int STEP = 1;
    private static final int EXACT_START = 2;
    private static final int EXACT_MIDDLE = 3;
    /** The arrows' depth apart (m), so that the narrower ones draw over the wider. */
    private static final float DEPTH_STEP = 0.01f;
    /**
     * The graph's text when presenting, as a fraction of the slide's text: the energy bars'
     * fraction, so the strip's two views read alike.
     */
    private static final float PRESENT_TEXT_FRACTION = 0.6f;

    private DemoState demo;
    private DemoParticle followed;
    /** The sphere's exact path, for the tangent at the middle (null until followed). */
    private ExactPath exact;
    private final DerivativeLens lens = new DerivativeLens();
    private boolean on;
    /** The arrows (null without a window). */
    private VelocityArrow[] arrows;
    /** Scratch: the exact tangent at the middle (m/s) and an arrow's start (m). */
    private final Vector3f middleTangent = new Vector3f();
    private final Vector3f arrowStart = new Vector3f();
    /** The sphere's radius, which sizes the arrows (m). */
    private final float radiusMetres;
    /** The steps plotted and picked from. */
    private final LensSteps steps = new LensSteps();
    private final StepDotPick dotPick = new StepDotPick();
    /** The followed sphere's place among the demo's particles (-1 until known). */
    private int particleIndex = -1;
    /** The graph (null without a window). */
    private LensGraph graph;
    /** The strip's part the graph was last laid out in, and at which text size. */
    private final ScreenRect graphSlot = new ScreenRect();
    private final ScreenRect graphRect = new ScreenRect();
    private float graphTextSize = Float.NaN;
    /** Whether the graph's room was asked for presenting (its text is larger then). */
    private boolean graphPresenting;
    /** What the HUD says when the step re-taken is not the one the sphere takes (or null). */
    private String stepNote;

    /**
     * Create the part.
     *
     * @param sphereRadiusMetres the followed sphere's drawn radius (in metres, &gt;0)
     */
    public LensPart(float sphereRadiusMetres) {
        if (!(sphereRadiusMetres > 0f) || Float.isInfinite(sphereRadiusMetres)) {
            throw new IllegalArgumentException("sphere radius " + sphereRadiusMetres
                    + " m: allowed a finite radius > 0");
        }
        radiusMetres = sphereRadiusMetres;
    }

    /**
     * Look at the steps of this sphere. Call in the demo's {@code createScene()}.
     *
     * @param sphere the followed sphere (not null)
     */
    public void follow(DemoParticle sphere) {
        followed = sphere;
        exact = new ExactPath(sphere.getPathIntegrator());
    }

    @Override
    public void attach(DemoState newDemo) {
        demo = newDemo;
    }

    @Override
    public void declareParameters(DemoParameters parameters) {
        parameters.add(DemoParameter.choice(PARAMETER, "derivative lens",
                new String[] {"off", "on"}, 0, DemoParameter.Applies.LIVE,
                value -> on = Math.round(value) == 1));
    }

    /** Bind O: the lens on and off, through the parameter so the panel shows it. */
    @Override
    public void declareKeys() {
        demo.bindKey(KEY, "O", "derivative lens: chord, V_i+1, exact dP/dt",
                () -> demo.getParameters().set(PARAMETER, on ? 0f : 1f));
    }

    @Override
    public void buildViews(Application app) {
        Material unshaded = new Material(app.getAssetManager(),
                "Common/MatDefs/Misc/Unshaded.j3md");
        arrows = new VelocityArrow[COLORS.length];
        Node scene = demo.getSceneNode();
        for (int i = 0; i < arrows.length; ++i) {
            arrows[i] = new VelocityArrow("lens " + COLOR_NAMES[i], WIDTHS[i] * radiusMetres,
                    ARROW_SECONDS, COLORS[i], unshaded);
            arrows[i].setVisible(false);
            scene.attachChild(arrows[i].getGeometry());
        }
        graph = new LensGraph(app.getAssetManager(), HudFont.load(app.getAssetManager()));
        graph.setVisible(false);
        demo.getWindow().getDragControl().addClickTarget(this::clickStepDot);
    }

    /**
     * Once a frame: look at the shown step, point the arrows and draw the graph. Allocates
     * nothing but when the graph's room in the strip comes or goes.
     */
    @Override
    public void afterFrame() {
        boolean looking = look();
        if (arrows == null) {
            return;
        }
        for (int i = 0; i < arrows.length; ++i) {
            arrows[i].setVisible(looking);
        }
        drawGraph(looking);
        if (!looking) {
            return;
        }
        pointArrow(CHORD, lens.chord);
        pointArrow(STEP, lens.stepVelocity);
        pointArrow(EXACT_START, lens.exactAtStart);
        pointArrow(EXACT_MIDDLE, lens.exactAtMiddle);
    }

    /**
     * Say on the HUD, under the lens's first line, that the step it re-takes (the recipe's,
     * with the sphere's own forces) is not the one the sphere takes: a demo whose spheres
     * run other forces or another method sets it before the parts write their lines.
     *
     * @param note one line without its newline, or null when the lens shows the sphere's step
     */
    public void setStepNote(String note) {
        stepNote = note;
    }

    @Override
    public void writeHudLines(StringBuilder text) {
        if (!on) {
            return;
        }
        if (!look()) {
            text.append("derivative lens (O): the sphere is not flying;"
                    + " click a step dot of its flight\n");
            return;
        }
        text.append("derivative lens (O; click a step dot) at step ")
                .append(demo.getRun().getShownStep())
                .append(", t_i = ");
        TextFormat.appendFixed(text, demo.getWorld().getTimeSeconds(), 3).append(" s, h = ");
        TextFormat.appendFixed(text, lens.getStepSeconds(), 4)
                .append(" s; arrows from P_i, in m/s:\n");
        if (stepNote != null) {
            text.append("  ").append(stepNote).append('\n');
        }
        appendLine(text, CHORD, "chord (P_i+1 - P_i)/h", lens.chord);
        appendLine(text, STEP, "V_i+1, the step's velocity", lens.stepVelocity);
        appendLine(text, EXACT_START, "exact dP/dt at t_i", lens.exactAtStart);
        appendLine(text, EXACT_MIDDLE, "exact dP/dt at t_i + h/2", lens.exactAtMiddle);
    }

    /**
     * Presenting, one formula line when the slide has room for it: the four values' y
     * components (the arrows' differences under gravity are in y).
     */
    @Override
    public void writePresentation(Presentation slide) {
        if (slide.countFormulaLines() >= Presentation.MAX_FORMULA_LINES || !look()) {
            return;
        }
        // short enough for one line of the slide's type at 1280x720
        StringBuilder line = slide.formula().append("V_y: chord ");
        TextFormat.appendFixed(line, lens.chord.y, DECIMALS).append(", V_i+1 ");
        TextFormat.appendFixed(line, lens.stepVelocity.y, DECIMALS).append(", dP/dt ");
        TextFormat.appendFixed(line, lens.exactAtStart.y, DECIMALS).append(" (t_i) ");
        TextFormat.appendFixed(line, lens.exactAtMiddle.y, DECIMALS).append(" (mid)");
    }

    /**
     * A press on the scene that no grip or sphere took: if it is on a step dot of the
     * followed sphere's trail, of a step the replay ring holds, show that step (paused), as
     * the timeline would, so the lens looks at it.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param screenX the press's x (in pixels from the window's left edge)
     * @param screenY the press's y (in pixels from the window's bottom edge)
     * @return true if a step dot was chosen
     */
    boolean clickStepDot(Camera camera, float screenX, float screenY) {
        if (!on || !readSteps()) {
            return false;
        }
        int dot = dotPick.nearest(camera, steps.getPositions(), steps.countDots(), screenX,
                screenY, DragControl.MIN_PICK_PIXELS);
        if (dot < 0) {
            return false;
        }
        StateRing ring = demo.getRun().getStateRing();
        long entry = steps.getEntry(dot);
        if (ring.size() < 2) {
            demo.getClock().setPaused(true);
            return true;
        }
        // the timeline's place of the entry: scrubTo rounds it back to the same entry
        demo.getReplayControls().scrubTo((double) (entry - ring.getFirstIndex()) / (ring.size() - 1));
        return true;
    }

    /**
     * Access the steps the graph plots and a click picks from, as last read.
     *
     * @return the live steps (not null)
     */
    LensSteps getSteps() {
        return steps;
    }

    /**
     * Access the graph, for tests.
     *
     * @return the graph, or null without a window
     */
    public LensGraph getGraph() {
        return graph;
    }

    /** @return true if the lens is switched on */
    public boolean isOn() {
        return on;
    }

    /**
     * Access the lens, for tests: its fields hold the step last looked at.
     *
     * @return the live lens (not null)
     */
    public DerivativeLens getLens() {
        return lens;
    }

    /**
     * Look at the step from the followed sphere's shown state, if on and the sphere flies.
     * Allocates nothing.
     *
     * @return true if the lens holds that step
     */
    private boolean look() {
        if (!on || followed == null || followed.hasLanded() || followed.isParked()) {
            return false;
        }
        Particle particle = followed.getParticle();
        if (!Vector3f.isValidVector(particle.position)
                || !Vector3f.isValidVector(particle.velocity)) {
            return false;
        }
        float h = demo.getClock().getCurrentStepSeconds();
        lens.look(followed.getIntegrator(), particle.getMass(), particle.position,
                particle.velocity, h);
        exact.start(particle.position, particle.velocity, particle.getMass(), false);
        exact.advance(0.5 * h);
        middleTangent.set((float) exact.getVelocity(0), (float) exact.getVelocity(1),
                (float) exact.getVelocity(2));
        // The true motion through (P_i, V_i) has the tangent V_i at t_i.
        lens.setExactTangents(particle.velocity, middleTangent);
        return true;
    }

    /**
     * Read the followed sphere's steps from the ring, up to the one shown, and the step
     * looked at (or, when the lens does not look, the sphere's velocity now). Allocates
     * nothing.
     *
     * @return false if there is nothing to read (no sphere, no step recorded)
     */
    boolean readSteps() {
        StateRing ring = demo.getRun().getStateRing();
        if (followed == null || ring.size() == 0) {
            steps.clear();
            return false;
        }
        if (particleIndex < 0) {
            particleIndex = demo.getParticles().indexOf(followed);
        }
        if (look()) {
            steps.read(ring, demo.getRun().getShownStep(), particleIndex,
                    demo.getWorld().getTimeSeconds() + lens.getStepSeconds(), lens.stepVelocity);
        } else {
            steps.read(ring, demo.getRun().getShownStep(), particleIndex,
                    demo.getWorld().getTimeSeconds(), followed.getParticle().velocity);
        }
        return true;
    }

    /**
     * Ask for the graph's room in the strip (or give it back), and plot the steps in it.
     * Allocates nothing but when the room comes or goes.
     */
    private void drawGraph(boolean looking) {
        EnergyPart strip = demo.getEnergyPart();
        if (demo.getWindow().getHud() == null || strip == null) {
            return;
        }
        if (graph.getNode().getParent() == null) {
            // The HUD's node comes and goes with the demo: the graph with it.
            demo.getWindow().getHud().getNode().attachChild(graph.getNode());
        }
        boolean wanted = looking && readSteps();
        boolean presenting = demo.getDemoHud().isPresenting();
        float size = presenting ? PRESENT_TEXT_FRACTION * HudLayout.PRESENT_SIZE
                : HudLayout.SCENE_LABEL_SIZE;
        if (presenting != graphPresenting) {
            graphPresenting = presenting;
            graphTextSize = Float.NaN;
        }
        strip.askBelowBars(wanted ? graph.widthFor(size) : 0f,
                wanted ? graph.heightFor(size) : 0f);
        boolean visible = wanted && !demo.getWindow().getHud().isHelpVisible();
        graph.setVisible(visible);
        if (!visible) {
            return;
        }
        HudLayout layout = demo.getWindow().getHud().getLayout();
        strip.copyBelowBars(graphSlot);
        float textSize = layout.isPresenting()
                ? PRESENT_TEXT_FRACTION * layout.getBodySize() : layout.getSceneLabelSize();
        if (graphSlot.getX() != graphRect.getX() || graphSlot.getY() != graphRect.getY()
                || graphSlot.getWidth() != graphRect.getWidth()
                || graphSlot.getHeight() != graphRect.getHeight()
                || textSize != graphTextSize) {
            graphRect.set(graphSlot);
            graphTextSize = textSize;
            graph.layOut(graphRect, textSize);
        }
        graph.plot(steps.getTimes(), steps.getVelocityX(), steps.getVelocityY(), steps.size(),
                steps.getChosen(), demo.getRun().getShownStep(), steps.slopeX(), steps.slopeY());
    }

    private void pointArrow(int which, Vector3f velocity) {
        arrowStart.set(lens.startPosition);
        arrowStart.z += DEPTH_STEP * which;
        arrows[which].update(arrowStart, velocity);
    }

    private static void appendLine(StringBuilder text, int which, String name,
            Vector3f value) {
        text.append("  ").append(COLOR_NAMES[which]).append(": ").append(name).append(" = (");
        TextFormat.appendFixed(text, value.x, DECIMALS).append(", ");
        TextFormat.appendFixed(text, value.y, DECIMALS).append(")\n");
    }
}
