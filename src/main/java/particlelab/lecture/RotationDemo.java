package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.demo.StepTable;
import particlelab.demo.TrajectoryExport;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationCheck;
import particlelab.rigid.RotationIntegrator.Orientation;
import particlelab.rigid.RotationIntegrator;
import particlelab.rigid.SpinAngle;
import particlelab.view.BoxView;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.Body;

/**
 * Rotation, drift and cures: four identical boxes spin side by side at the same constant ω,
 * each turned by a different orientation step. Builds upon uniform motion (a constant rate,
 * integrated by Euler steps) and the rigid-body model of {@code docs/numerics.md} §9.
 *
 * <p>The lecture's rotation matrix R holds the body's axes as its columns; a point at body
 * coordinates b is at {@code R·b}. Spinning at ω, {@code Ṙ = [ω]×·R}, and the lecture's Euler
 * step is
 * <pre>
 *   plain Euler:  R ← R + h·[ω]×·R        (det R grows by 1 + (|ω|h)² per step)
 *   polar:        the same, then R ← the nearest rotation to R
 *   quaternion:   q ← q + (h/2)·(0, ω)·q, then q ← q/|q|
 *   exact:        R ← exp(h·[ω]×)·R        (Rodrigues' formula)
 * </pre>
 *
 * <p>What to watch for: the plain box grows and stretches in the plane across ω, because
 * {@code I + h·[ω]×} is a rotation times a stretch by {@code √(1 + (|ω|h)²)}; it is started
 * again when its det reaches {@value #DET_LIMIT} (half as large again across ω). The polar
 * and quaternion boxes stay rigid ({@code det R = 1} and {@code |RᵀR − I| ≈ 0} to float
 * round-off) but lag the exact rotation, by {@code ωh − atan(ωh)} and {@code ωh −
 * 2·atan(ωh/2)} per step: a larger h (Right) makes the lag visible. The exact box stays on
 * the exact angle. The plain box's angle error is that of its nearest rotation, which for a
 * constant ω is the polar box itself (the cure removes the stretch, not the lag), so the two
 * read the same. The boxes are drawn by moving their vertices with R itself, so what you
 * see is the matrix, drift and all.
 *
 * <p>Two numbers per box say how far it is behind: the angle to the exact rotation, a distance
 * between orientations that wraps at 180° (a box a whole turn behind reads 0°), and the lag,
 * the exact angle {@code |ω|·t} minus the angle the box has turned about ω, summed step by step
 * so that it never wraps ({@link SpinAngle}). At {@code |ω|h = 0.8} (Up Up Right Right) the
 * polar box soon lags by more than a turn and its angle to the exact rotation falls again,
 * below the quaternion's: only the lag ranks them right. The plain box's line names its last
 * restart and its time for {@value #RESTART_NOTE_SECONDS} s of simulated time after it (a box
 * that has just started again reads det 1 and no error, which is not accuracy), and a line
 * below the boxes gives the restart rule and the count.
 */
public final class RotationDemo extends DemoState {

    /** The plain box starts again once its det R reaches this (1.5³). */
    public static final float DET_LIMIT = 3.375f;
    /** How long the plain box's line names its last restart (simulated seconds). */
    public static final float RESTART_NOTE_SECONDS = 2f;
    /** The starting spin rate |ω| (rad/s), and its range for the keys. */
    public static final float DEFAULT_OMEGA = 3f;
    public static final float MIN_OMEGA = 0.75f;
    public static final float MAX_OMEGA = 12f;
    /** The |ω| the keys and the panel step through (rad/s): halving and doubling. */
    private static final float[] OMEGA_STOPS = {0.75f, 1.5f, 3f, 6f, 12f};
    /** The range of h for the keys (s): the shared step parameter's, so --set reaches it. */
    public static final float MIN_STEP = 1f / 240f;
    public static final float MAX_STEP = 1f / 15f;
    /** The spin axis, tilted toward the camera so the boxes tumble (unit vector). */
    public static final Vector3f AXIS = new Vector3f(0.2f, 0.4f, 0.9f).normalizeLocal();
    /** The orientation steps, left to right. */
    public static final Orientation[] METHODS = {Orientation.EULER, Orientation.POLAR,
        Orientation.QUATERNION, Orientation.EXACT};
    private static final String[] NAMES = {"plain Euler", "polar", "quaternion", "exact"};
    private static final ColorRGBA[] COLORS = {new ColorRGBA(1f, 0.45f, 0.3f, 1f),
        new ColorRGBA(0.35f, 0.8f, 1f, 1f), new ColorRGBA(0.6f, 1f, 0.45f, 1f),
        new ColorRGBA(1f, 0.85f, 0.35f, 1f)};
    private static final Vector3f HALF_EXTENTS = new Vector3f(0.7f, 0.45f, 0.3f);
    /** Each box's inertia (1 kg): unused by the torque-free turn without gyroscopic term. */
    private static final Inertia BOX_INERTIA = Inertia.box(1f, 2f * HALF_EXTENTS.x,
            2f * HALF_EXTENTS.y, 2f * HALF_EXTENTS.z);
    /** Where the boxes spin: their x, and the common height (m). */
    private static final float FIRST_X = 2f;
    private static final float SPACING_X = 3.5f;
    private static final float BOX_Y = 3.5f;
    private static final float POST_HEIGHT = 1f;
    /** The boxes spin in front of the grid's plane, so no grid line shows on them (m). */
    private static final float BOX_Z = 1.3f;
    private static final float RAD_TO_DEG = (float) (180.0 / Math.PI);
    /**
     * The header of each box's export table, one row per step: the time, the time since the
     * box last started from the identity, R row by row, det R, |RᵀR − I| and the angle error
     * against the exact rotation.
     */
    public static final String BOX_HEADER = "t_s,box_t_s,r00,r01,r02,r10,r11,r12,r20,r21,r22,"
            + "det,orthogonality_error,angle_error_deg";

    /** The boxes as bodies of the world, at rest: the world turns them, step by step. */
    private final RigidBody[] boxes = new RigidBody[METHODS.length];
    /** Each box's R (its rigid body's live orientation). */
    private final Matrix3f[] orientations = new Matrix3f[METHODS.length];
    private final RotationIntegrator[] integrators = new RotationIntegrator[METHODS.length];
    private final BoxView[] views = new BoxView[METHODS.length];
    /** Each box's R before the last step, for the views to draw between steps. */
    private final Matrix3f[] previousOrientations = new Matrix3f[METHODS.length];
    private final Vector3f[] centres = new Vector3f[METHODS.length];
    /** Per box: the time since it started from the identity (s), for its exact rotation. */
    private final double[] elapsedSeconds = new double[METHODS.length];
    /** Per box: the angle it has turned about ω since it started, unwrapped. */
    private final SpinAngle[] spinAngles = new SpinAngle[METHODS.length];
    /** The simulated time since the demo (re)started (s): the exact box never restarts. */
    private double runSeconds;
    /** When the plain box last started again on its own (s of {@link #runSeconds}), or NaN. */
    private double plainRestartSeconds = Double.NaN;
    private final RotationCheck check = new RotationCheck();
    private final Matrix3f identity = new Matrix3f();
    private final Matrix3f exact = new Matrix3f();
    private final Vector3f omega = new Vector3f();
    /** Per box: its states after each step, for the export. */
    private final StepTable[] tables = new StepTable[METHODS.length];
    /** The time simulated since the last restart (in seconds). */
    private double simulatedSeconds;
    private float omegaMagnitude = DEFAULT_OMEGA;
    private int plainRestarts;
    private KeyBinding fasterKey;
    private KeyBinding slowerKey;
    private KeyBinding longerKey;
    private KeyBinding shorterKey;

    /** Create the demo. */
    public RotationDemo() {
        super("Rotation (drift and cures)");
        for (int i = 0; i < METHODS.length; ++i) {
            // Torque-free and without the gyroscopic term, ω stays exactly what it was set
            // to: the box turns at the constant ω the drift is measured against.
            integrators[i] = new RotationIntegrator(METHODS[i],
                    RotationIntegrator.Angular.EXPLICIT, false);
            centres[i] = new Vector3f(FIRST_X + SPACING_X * i, BOX_Y, BOX_Z);
            spinAngles[i] = new SpinAngle();
            tables[i] = new StepTable("rotation-" + TrajectoryExport.fileSafeName(NAMES[i]),
                    BOX_HEADER, StepTable.DEFAULT_CAPACITY);
        }
        omega.set(AXIS).multLocal(omegaMagnitude);
    }

    /**
     * Access one box's orientation R.
     *
     * @param box 0 to 3, in the order of {@link #METHODS}
     * @return the live matrix (not null; do not modify)
     */
    public Matrix3f getOrientation(int box) {
        getWorld();
        return orientations[box];
    }

    /**
     * Return how long one box has turned since it last started from the identity.
     *
     * @param box 0 to 3, in the order of {@link #METHODS}
     * @return the time (in seconds, &ge;0)
     */
    public double getElapsedSeconds(int box) {
        return elapsedSeconds[box];
    }

    /**
     * Return how far one box lags the exact rotation in accumulated angle: {@code |ω|·t} minus
     * the angle it has turned about ω since it last started, unwrapped (see {@link SpinAngle}).
     *
     * @param box 0 to 3, in the order of {@link #METHODS}
     * @return the lag (in radians; positive when behind; grows past 2π)
     */
    public double getLagRadians(int box) {
        return spinAngles[box].lagRadians(omegaMagnitude * elapsedSeconds[box]);
    }

    /**
     * Return when the plain box last started again on its own, reaching {@link #DET_LIMIT}.
     *
     * @return the time since the demo started (in seconds), or NaN if it has not since then
     */
    public double getPlainRestartSeconds() {
        return plainRestartSeconds;
    }

    /**
     * Copy the common ω into storeResult.
     *
     * @param storeResult storage for ω (in rad/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyOmega(Vector3f storeResult) {
        return storeResult.set(omega);
    }

    /**
     * Count how often the plain box reached {@link #DET_LIMIT} and started again.
     *
     * @return the count (&ge;0)
     */
    public int countPlainRestarts() {
        return plainRestarts;
    }

    /**
     * Access the view of one box.
     *
     * @param box 0 to 3, in the order of {@link #METHODS}
     * @return the view (null before initialisation)
     */
    public BoxView getView(int box) {
        return views[box];
    }

    @Override
    protected void createScene() {
        // No particles: the boxes are bodies at rest with no force, so the world only turns
        // them (the translation step leaves them where they are). A post names each box.
        ParticleIntegrator noForce = new ParticleIntegrator();
        for (int i = 0; i < METHODS.length; ++i) {
            Body body = getWorld().addBody(noForce, centres[i], Vector3f.ZERO, 1f, 0f);
            boxes[i] = new RigidBody(body.getParticle(), BOX_INERTIA);
            body.setRotation(boxes[i], integrators[i]);
            orientations[i] = boxes[i].orientation;
            previousOrientations[i] = new Matrix3f(orientations[i]);
            boxes[i].angularVelocity.set(omega);
            spinAngles[i].start(orientations[i], omega);
            addMarker(NAMES[i], centres[i].x, POST_HEIGHT, COLORS[i]);
        }
        setView(0f, FIRST_X * 2f + SPACING_X * (METHODS.length - 1), 5.2f, 1f, 5, 0.3f);
        addStateRecord(runState());
    }

    @Override
    protected void declareParameters() {
        // |ω|, as the Up and Down keys double and halve it; h is the shared step parameter.
        declareParameter(new DemoParameter("omega", "spin |ω|", "rad/s", MIN_OMEGA, MAX_OMEGA,
                MIN_OMEGA, DEFAULT_OMEGA, 2, DemoParameter.Applies.LIVE, value -> {
                    if (value != omegaMagnitude) {
                        setOmega(value);
                    }
                }).withStops(OMEGA_STOPS));
    }

    @Override
    protected void declareKeys() {
        fasterKey = bindKey(KeyInput.KEY_UP, "Up", "|ω| x2 (restarts the boxes)",
                () -> changeOmega(2f));
        slowerKey = bindKey(KeyInput.KEY_DOWN, "Down", "|ω| /2 (restarts the boxes)",
                () -> changeOmega(0.5f));
        longerKey = bindKey(KeyInput.KEY_RIGHT, "Right", "h x2 (fixed step)",
                () -> changeStep(2f));
        shorterKey = bindKey(KeyInput.KEY_LEFT, "Left", "h /2 (fixed step)",
                () -> changeStep(0.5f));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("dR/dt = [ω]×R, one step of h:  plain Euler R += h[ω]×R;  polar: the same,"
                + " then the nearest rotation\n");
        text.append("quaternion: q += (h/2)(0,ω)q, then q /= |q|;  exact: R = exp(h[ω]×)R"
                + " (Rodrigues)\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("|ω| = ");
        TextFormat.appendFixed(text, omegaMagnitude, 2).append(" rad/s (").append(
                fasterKey.getKeyLabel()).append('/').append(slowerKey.getKeyLabel())
                .append("),  h (").append(longerKey.getKeyLabel()).append('/')
                .append(shorterKey.getKeyLabel()).append("):  |ω|h = ");
        TextFormat.appendFixed(text, omegaMagnitude * getClock().getStepSeconds(), 4)
                .append(",  plain det grows x");
        double growth = 1.0 + square(omegaMagnitude * getClock().getStepSeconds());
        TextFormat.appendFixed(text, growth, 6).append(" per step\n");
        for (int i = 0; i < METHODS.length; ++i) {
            Matrix3f r = orientations[i];
            check.exactRotation(identity, omega, elapsedSeconds[i], exact);
            text.append(NAMES[i]).append(":  det R = ");
            TextFormat.appendFixed(text, check.determinant(r), 6).append(",  |R^T·R − I| = ");
            TextFormat.appendFixed(text, check.orthogonalityError(r), 6)
                    .append(",  to exact = ");
            TextFormat.appendFixed(text, RAD_TO_DEG * check.angleError(r, exact), 4)
                    .append("°,  lag = ");
            TextFormat.appendFixed(text, RAD_TO_DEG * getLagRadians(i), 2).append('°');
            if (i == 0 && runSeconds - plainRestartSeconds <= RESTART_NOTE_SECONDS) {
                text.append("   RESTARTED at t = ");
                TextFormat.appendFixed(text, plainRestartSeconds, 2).append(" s");
            }
            text.append('\n');
        }
        text.append(NAMES[0]).append(" starts again from R = I when det R reaches ");
        TextFormat.appendFixed(text, DET_LIMIT, 3).append(": ").append(plainRestarts)
                .append(plainRestarts == 1 ? " time" : " times").append(" so far\n");
    }

    /**
     * The plain box starts again from R = I once its determinant has reached the limit:
     * before the next step, where the demo may move things (its hook after a step only
     * watches).
     */
    @Override
    protected void beforeStep(float stepSeconds) {
        if (check.determinant(orientations[0]) >= DET_LIMIT) {
            orientations[0].loadIdentity();
            elapsedSeconds[0] = 0.0;
            spinAngles[0].start(orientations[0], omega);
            ++plainRestarts;
            plainRestartSeconds = runSeconds;
        }
        // What the views blend from: the boxes as this step starts.
        keepPreviousOrientations();
    }

    @Override
    protected void afterStep(float stepSeconds) {
        // The world turned the boxes; this follows their angles and records them.
        runSeconds += stepSeconds;
        for (int i = 0; i < METHODS.length; ++i) {
            elapsedSeconds[i] += stepSeconds;
            spinAngles[i].add(orientations[i]);
        }
        simulatedSeconds += stepSeconds;
        for (int i = 0; i < METHODS.length; ++i) {
            record(i);
        }
    }

    @Override
    protected void afterFrame() {
        updateBoxes();
    }

    /**
     * Add the boxes' states per step to an export, one table each
     * ({@code rotation-<box>.csv}, {@link #BOX_HEADER}): the demo has no particle to trace.
     *
     * @param storeResult where to add the tables (not null, modified)
     */
    @Override
    public void collectExportTables(List<StepTable> storeResult) {
        for (StepTable table : tables) {
            storeResult.add(table);
        }
    }

    @Override
    protected void onRestart() {
        for (int i = 0; i < METHODS.length; ++i) {
            orientations[i].loadIdentity();
            boxes[i].angularVelocity.set(omega);
            elapsedSeconds[i] = 0.0;
            spinAngles[i].start(orientations[i], omega);
        }
        keepPreviousOrientations();
        runSeconds = 0.0;
        plainRestartSeconds = Double.NaN;
        plainRestarts = 0;
        simulatedSeconds = 0.0;
        for (StepTable table : tables) {
            table.clear();
        }
        updateBoxes();
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        for (int i = 0; i < METHODS.length; ++i) {
            views[i] = new BoxView(app.getAssetManager(), NAMES[i] + " box", HALF_EXTENTS,
                    COLORS[i]);
            getSceneNode().attachChild(views[i].getGeometry());
        }
        updateBoxes();
    }

    /** Record one box's state after a step. Allocates nothing. */
    private void record(int box) {
        Matrix3f r = orientations[box];
        check.exactRotation(identity, omega, elapsedSeconds[box], exact);
        StepTable table = tables[box].startRow().put(simulatedSeconds).put(elapsedSeconds[box]);
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                table.put(r.get(row, column));
            }
        }
        table.put(check.determinant(r)).put(check.orthogonalityError(r))
                .put(RAD_TO_DEG * check.angleError(r, exact));
    }

    /**
     * Draw each box between its last two states, at this frame's blend (F6; 1 when paused,
     * replaying or drawing raw steps).
     */
    private void updateBoxes() {
        float alpha = getWindow().getDrawBlend();
        for (int i = 0; i < METHODS.length; ++i) {
            if (views[i] != null) {
                views[i].update(previousOrientations[i], centres[i], orientations[i],
                        centres[i], alpha);
            }
        }
    }

    /** Copy each box's R as the state the views blend from. Allocates nothing. */
    private void keepPreviousOrientations() {
        for (int i = 0; i < METHODS.length; ++i) {
            previousOrientations[i].set(orientations[i]);
        }
    }

    private void changeOmega(float factor) {
        setOmega(Math.max(MIN_OMEGA, Math.min(MAX_OMEGA, omegaMagnitude * factor)));
    }

    private void setOmega(float magnitude) {
        omegaMagnitude = magnitude;
        omega.set(AXIS).multLocal(omegaMagnitude);
        // The panel and --set show the |ω| the keys chose.
        getParameters().set("omega", magnitude);
        restart();
    }

    private void changeStep(float factor) {
        SimulationClock clock = getClock();
        float step = Math.max(MIN_STEP, Math.min(MAX_STEP, clock.getStepSeconds() * factor));
        clock.setStepSeconds(step);
        getParameters().set("h", step);
        // The keys set the fixed step; the HUD's stepping line shows the new h.
        clock.setMode(SimulationClock.Mode.FIXED_STEP);
    }

    private static double square(double x) {
        return x * x;
    }

    /**
     * The demo's own state, for the ring: the run's clock, each box's time and spin angle,
     * the plain box's restarts and each box's table's length.
     */
    private StateRecord runState() {
        double[] angles = new double[SpinAngle.STATE_DOUBLES];
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 2 + 2 + 2 + 1 + METHODS.length * (2 + 2 * SpinAngle.STATE_DOUBLES + 3);
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putDouble(runSeconds);
                slab.putDouble(simulatedSeconds);
                slab.putDouble(plainRestartSeconds);
                slab.putInt(plainRestarts);
                for (int i = 0; i < METHODS.length; ++i) {
                    slab.putDouble(elapsedSeconds[i]);
                    spinAngles[i].copyState(angles, 0);
                    for (int k = 0; k < angles.length; ++k) {
                        slab.putDouble(angles[k]);
                    }
                    tables[i].writeState(slab);
                }
            }

            @Override
            public void readState(StateSlab slab) {
                runSeconds = slab.getDouble();
                simulatedSeconds = slab.getDouble();
                plainRestartSeconds = slab.getDouble();
                plainRestarts = slab.getInt();
                for (int i = 0; i < METHODS.length; ++i) {
                    elapsedSeconds[i] = slab.getDouble();
                    for (int k = 0; k < angles.length; ++k) {
                        angles[k] = slab.getDouble();
                    }
                    spinAngles[i].setState(angles, 0);
                    tables[i].readState(slab);
                }
                // A step back: the views blend from the state put back, not a later one.
                keepPreviousOrientations();
            }
        };
    }

    /** The slide: plain Euler's growth per step; its determinant now. */
    @Override
    protected void writePresentation(Presentation slide) {
        slide.formula().append("plain Euler R += h[ω]×R:  det R x(1 + (|ω|h)²) per step");
        float omegaH = omegaMagnitude * getClock().getStepSeconds();
        StringBuilder formula = slide.formula().append("|ω|h = ");
        TextFormat.appendFixed(formula, omegaH, 4).append(":  x");
        TextFormat.appendFixed(formula, 1.0 + square(omegaH), 6).append(" per step");
        StringBuilder readout = slide.readout().append(NAMES[0]).append(":  det R = ");
        TextFormat.appendFixed(readout, check.determinant(orientations[0]), 6);
    }
}
