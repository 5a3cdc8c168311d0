package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.physics.ParticleIntegrator;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationCheck;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator;
import particlelab.view.BoxView;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.Body;

/**
 * Tennis racket: the intermediate-axis flip. A torque-free flat box with principal moments
 * (1, 2, 3) kg·m² is spun almost exactly about its middle axis (body y). Builds upon the
 * rotation demo; here ω itself changes, by Euler's equations in the body frame,
 * {@code I·ω̇ = −ω × (I·ω)} (no torque, only the gyroscopic term).
 *
 * <p>Spin about the smallest or the largest axis is stable; about the middle one it is not:
 * the tiny sideways spin grows until the box turns over, half a turn about another axis,
 * then comes back, again and again. Each flip is a sign change of the body-frame
 * {@code ωy}; the HUD lists the flip times and the period of {@code ωy} (two flips).
 *
 * <p>What to watch for: two rackets side by side, the same plate from the same start, turned
 * by the same world with the same clock: on the left its ω stepped by explicit Euler, on the
 * right by the implicit midpoint, a post under each naming its method. Their front faces
 * (bright) and back faces (dark) swap every few seconds; explicit Euler gains kinetic energy
 * and |L| every step (its HUD drift grows, its flips drift from the midpoint's), implicit midpoint
 * keeps both to round-off, and the HUD gives the angle between the two plates as they part.
 * I shows both, explicit Euler alone or the midpoint alone (the other slot stays empty; both
 * are stepped all the time, so the HUD still compares them). G leaves out the gyroscopic
 * term (as some engines do): then ω stays constant and neither racket ever flips.
 */
public final class TennisRacketDemo extends DemoState {

    /** The principal moments (kg·m²): a flat plate, C = A + B. */
    public static final Inertia INERTIA = Inertia.of(1f, 2f, 3f);
    /** The starting spin in the body frame: mostly about y, a little about x and z (rad/s). */
    public static final Vector3f BODY_SPIN = new Vector3f(0.1f, 4f, 0.1f);
    /** The methods, in the order of the HUD lines. */
    public static final Angular[] METHODS = {Angular.EXPLICIT, Angular.IMPLICIT_MIDPOINT};
    private static final String[] NAMES = {"explicit Euler", "implicit midpoint"};
    /** The value of {@link #getShownMethod()} that shows both rackets. */
    public static final int BOTH = METHODS.length;
    /** The {@code method} parameter's names: one racket alone, by index, or both. */
    private static final String[] SHOWN_NAMES = {"explicit", "midpoint", "both"};
    /** Each racket's front-face colour, in the order of {@link #METHODS}. */
    private static final ColorRGBA[] COLORS = {new ColorRGBA(1f, 0.55f, 0.3f, 1f),
        new ColorRGBA(0.35f, 0.75f, 1f, 1f)};
    /** The starting tilt toward the camera, so the plate's face is seen (rad). */
    private static final float TILT = -0.45f;
    /** The plate's half sides, with the proportions that give moments (1, 2, 3) (m). */
    private static final Vector3f HALF_EXTENTS = new Vector3f(1.414f, 1f, 0.04f);
    /**
     * How far each racket's centre is from x = 0 (m): more than the plate's half diagonal
     * (1.73 m) as the perspective enlarges it, so the two never touch on the screen.
     */
    private static final float SLOT_X = 2.9f;
    /** The height of the rackets' centres (m). */
    private static final float CENTRE_Y = 3.1f;
    /** The rackets spin in front of the grid's plane, so no grid line shows on them (m). */
    private static final float CENTRE_Z = 1.8f;
    /** The posts naming the methods (m): short, below the lowest corner's reach. */
    private static final float POST_HEIGHT = 0.35f;
    /** How many flip times are kept per method. */
    private static final int FLIPS_KEPT = 64;
    private static final int FLIPS_SHOWN = 6;

    private final RigidBody[] bodies = new RigidBody[METHODS.length];
    /** The world's bodies the rigid bodies turn about, one per method. */
    private final Body[] worldBodies = new Body[METHODS.length];
    /** Per method: the integrator with the gyroscopic term, and without it. */
    private final RotationIntegrator[] integrators = new RotationIntegrator[METHODS.length];
    private final RotationIntegrator[] withoutGyroscopic =
            new RotationIntegrator[METHODS.length];
    private boolean gyroscopic = true;
    private final double[] startEnergy = new double[METHODS.length];
    private final double[] startMomentum = new double[METHODS.length];
    private final double[][] flipTimes = new double[METHODS.length][FLIPS_KEPT];
    private final int[] flips = new int[METHODS.length];
    private final boolean[] positiveWy = new boolean[METHODS.length];
    private final Vector3f bodyOmega = new Vector3f();
    /** Where each racket spins, left and right of x = 0 (m). */
    private final Vector3f[] centres = {new Vector3f(-SLOT_X, CENTRE_Y, CENTRE_Z),
        new Vector3f(SLOT_X, CENTRE_Y, CENTRE_Z)};
    private final Matrix3f tilt = new Matrix3f();
    /** Measures the angle between the two plates. */
    private final RotationCheck check = new RotationCheck();
    /** 0 or 1: that method's racket alone; {@link #BOTH}: both. */
    private int shown = BOTH;
    private double elapsedSeconds;
    private final BoxView[] views = new BoxView[METHODS.length];
    /** Each racket's R as the last step started, for the views to draw between steps. */
    private final Matrix3f[] previousOrientations = new Matrix3f[METHODS.length];
    private KeyBinding methodKey;
    private KeyBinding gyroscopicKey;

    /** Create the demo. */
    public TennisRacketDemo() {
        super("Tennis racket (intermediate axis)");
        // The slide is about energy: presenting shows the ledger's bars.
        getEnergyPart().showOnSlide();
        for (int i = 0; i < METHODS.length; ++i) {
            integrators[i] = new RotationIntegrator(RotationIntegrator.Orientation.EXACT,
                    METHODS[i], true);
            withoutGyroscopic[i] = new RotationIntegrator(
                    RotationIntegrator.Orientation.EXACT, METHODS[i], false);
        }
        tilt.fromAngleNormalAxis(TILT, Vector3f.UNIT_X);
    }

    /**
     * Access the view of the racket stepped by one method.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @return the live view (null before the window)
     */
    public BoxView getView(int method) {
        return views[method];
    }

    /**
     * Access the body stepped by one method.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @return the live body (not null)
     */
    public RigidBody getBody(int method) {
        getWorld();
        return bodies[method];
    }

    /**
     * Count the flips (sign changes of body-frame ωy) one method's body made.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @return the count (&ge;0)
     */
    public int countFlips(int method) {
        return flips[method];
    }

    /**
     * Return the time of one flip.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @param flip 0 for the first (less than {@link #countFlips} and {@value #FLIPS_KEPT})
     * @return the time (in seconds since the start)
     */
    public double getFlipSeconds(int method, int flip) {
        return flipTimes[method][flip];
    }

    /**
     * Return which rackets are shown.
     *
     * @return 0 for explicit Euler alone, 1 for implicit midpoint alone, {@link #BOTH} for
     *     both side by side
     */
    public int getShownMethod() {
        return shown;
    }

    /**
     * Test whether one method's racket is drawn.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @return true if it is shown (alone or beside the other)
     */
    public boolean isShown(int method) {
        return shown == BOTH || shown == method;
    }

    /**
     * Access where one method's racket spins: its body's position, left or right of x = 0.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @return the live centre (in metres, not null; do not modify)
     */
    public Vector3f getCentre(int method) {
        return centres[method];
    }

    /**
     * Return the angle between the two rackets' orientations, the explicit one's nearest
     * rotation against the midpoint's: 0 while they agree, up to 180° once they part.
     *
     * @return the angle (in radians, from 0 to π)
     */
    public double angleBetweenRadians() {
        getWorld();
        return check.angleError(bodies[0].orientation, bodies[1].orientation);
    }

    /**
     * Keep or leave out the gyroscopic term, and start again.
     *
     * @param on true for Euler's equations in full, false to leave out {@code ω × (I·ω)}
     */
    public void setGyroscopic(boolean on) {
        gyroscopic = on;
        getParameters().set("gyro", on ? 1 : 0);
        for (int i = 0; i < METHODS.length; ++i) {
            worldBodies[i].setRotation(bodies[i], rotationStep(i));
        }
        restart();
    }

    /**
     * Access the orientation every run starts from.
     *
     * @return the live matrix (not null; do not modify)
     */
    public Matrix3f getStartOrientation() {
        return tilt;
    }

    @Override
    protected void createScene() {
        // One body per method, with no force and at rest: the world steps only its rotation
        // (the translation step leaves a body at rest where it is). A post names each.
        ParticleIntegrator noForce = new ParticleIntegrator();
        for (int i = 0; i < METHODS.length; ++i) {
            worldBodies[i] = getWorld().addBody(noForce, centres[i], Vector3f.ZERO, 1f, 0f);
            bodies[i] = new RigidBody(worldBodies[i].getParticle(), INERTIA);
            worldBodies[i].setRotation(bodies[i], rotationStep(i));
            previousOrientations[i] = new Matrix3f();
            addMarker(NAMES[i], centres[i].x, POST_HEIGHT, COLORS[i]);
        }
        resetBodies();
        // Both slots with room for a plate's half diagonal, enlarged by the perspective.
        setView(-2f * SLOT_X, 2f * SLOT_X, 5.8f, 1f, 2, 0.3f);
        addStateRecord(flipState());
    }

    @Override
    protected void declareParameters() {
        // The rackets shown and the gyroscopic term, as the I and G keys switch them.
        declareParameter(DemoParameter.choice("method", "rackets shown", SHOWN_NAMES, shown,
                DemoParameter.Applies.LIVE, value -> show(Math.round(value))));
        declareParameter(DemoParameter.choice("gyro", "gyroscopic term",
                new String[] {"off", "on"}, gyroscopic ? 1 : 0, DemoParameter.Applies.LIVE,
                value -> {
                    if ((Math.round(value) == 1) != gyroscopic) {
                        setGyroscopic(Math.round(value) == 1);
                    }
                }));
    }

    @Override
    protected void declareKeys() {
        methodKey = bindKey(KeyInput.KEY_I, "I",
                "rackets shown: both -> explicit Euler -> implicit midpoint for ω",
                () -> getParameters().set("method", (shown + 1) % SHOWN_NAMES.length));
        gyroscopicKey = bindKey(KeyInput.KEY_G, "G",
                "gyroscopic term ω × (I·ω) on <-> off (starts again; off, it never flips)",
                () -> setGyroscopic(!gyroscopic));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("torque-free, body frame: I·dω/dt = −ω × (I·ω),  I = diag(1, 2, 3) kg·m²,"
                + "  ω0 = (0.1, 4, 0.1) rad/s,  R = exp(h[ω]×)·R\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        // Both rackets start from the same state: one E0 and one |L0| for both.
        text.append("shown (").append(methodKey.getKeyLabel()).append("): ")
                .append(shown == BOTH ? "both" : NAMES[shown]).append(",  gyroscopic term (")
                .append(gyroscopicKey.getKeyLabel()).append(") ")
                .append(gyroscopic ? "on" : "off").append(",  E0 = ");
        TextFormat.appendFixed(text, startEnergy[0], 3).append(" J,  |L0| = ");
        TextFormat.appendFixed(text, startMomentum[0], 3).append(" kg·m²/s\n");
        for (int i = 0; i < METHODS.length; ++i) {
            RigidBody body = bodies[i];
            text.append(NAMES[i]).append(":  E drift ");
            double energy = body.rotationalEnergy(bodyOmega);
            TextFormat.appendFixed(text, 100.0 * (energy / startEnergy[i] - 1.0), 4)
                    .append(" %,  |L| drift ");
            double momentum = body.angularMomentum(bodyOmega);
            TextFormat.appendFixed(text, 100.0 * (momentum / startMomentum[i] - 1.0), 4)
                    .append(" %,  ");
            int count = flips[i];
            if (count == 0) {
                text.append("no flip yet\n");
                continue;
            }
            text.append("flips at");
            int kept = Math.min(count, FLIPS_KEPT);
            for (int k = Math.max(0, kept - FLIPS_SHOWN); k < kept; ++k) {
                text.append(' ');
                TextFormat.appendFixed(text, flipTimes[i][k], 2);
            }
            text.append(" s,  ωy period: ");
            if (count >= 3) {
                // Two flips make one period of ωy: from + to − and back.
                TextFormat.appendFixed(text, flipTimes[i][kept - 1] - flipTimes[i][kept - 3], 3)
                        .append(" s\n");
            } else {
                text.append("after 3 flips\n");
            }
        }
        text.append("explicit Euler vs implicit midpoint: the plates are ");
        TextFormat.appendFixed(text, Math.toDegrees(angleBetweenRadians()), 1)
                .append("° apart\n");
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        // What the views blend from: the plates as this step starts.
        keepPreviousOrientations();
    }

    @Override
    protected void afterStep(float stepSeconds) {
        // The world turned both plates; this only watches body-frame ωy change sign.
        elapsedSeconds += stepSeconds;
        for (int i = 0; i < METHODS.length; ++i) {
            boolean positive = bodies[i].bodyAngularVelocity(bodyOmega).y > 0f;
            if (positive != positiveWy[i]) {
                if (flips[i] < FLIPS_KEPT) {
                    flipTimes[i][flips[i]] = elapsedSeconds;
                }
                ++flips[i];
                positiveWy[i] = positive;
            }
        }
    }

    @Override
    protected void afterFrame() {
        updateView();
    }

    @Override
    protected void onRestart() {
        resetBodies();
        updateView();
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        for (int i = 0; i < METHODS.length; ++i) {
            views[i] = new BoxView(app.getAssetManager(), NAMES[i] + " racket", HALF_EXTENTS,
                    COLORS[i]);
            getSceneNode().attachChild(views[i].getGeometry());
        }
        show(shown);
    }

    private void resetBodies() {
        elapsedSeconds = 0.0;
        for (int i = 0; i < METHODS.length; ++i) {
            RigidBody body = bodies[i];
            body.setOrientation(tilt);
            // ω in the world frame = R·ω_b.
            tilt.mult(BODY_SPIN, body.angularVelocity);
            startEnergy[i] = body.rotationalEnergy(bodyOmega);
            startMomentum[i] = body.angularMomentum(bodyOmega);
            flips[i] = 0;
            positiveWy[i] = BODY_SPIN.y > 0f;
        }
        keepPreviousOrientations();
    }

    /** Copy each racket's R as the state the views blend from. Allocates nothing. */
    private void keepPreviousOrientations() {
        for (int i = 0; i < METHODS.length; ++i) {
            previousOrientations[i].set(bodies[i].orientation);
        }
    }

    private RotationIntegrator rotationStep(int method) {
        return gyroscopic ? integrators[method] : withoutGyroscopic[method];
    }

    /**
     * Show one racket alone or both: the method parameter's setter. Both are stepped either
     * way; a racket not shown leaves its slot empty.
     *
     * @param which 0 or 1 for that method alone, {@link #BOTH} for both
     */
    private void show(int which) {
        shown = which;
        for (int i = 0; i < METHODS.length; ++i) {
            if (views[i] != null) {
                views[i].getGeometry().setCullHint(isShown(i) ? Spatial.CullHint.Never
                        : Spatial.CullHint.Always);
            }
        }
        updateView();
    }

    /**
     * Draw each racket between its last two states, at this frame's blend (F6; 1 when
     * paused, replaying or drawing raw steps).
     */
    private void updateView() {
        float alpha = getWindow().getDrawBlend();
        for (int i = 0; i < METHODS.length; ++i) {
            if (views[i] != null) {
                views[i].update(previousOrientations[i], centres[i], bodies[i].orientation,
                        centres[i], alpha);
            }
        }
    }

    /** The demo's own state, for the ring: the clock and each plate's flips so far. */
    private StateRecord flipState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 2 + METHODS.length * (2 + 2 * FLIPS_KEPT);
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putDouble(elapsedSeconds);
                for (int i = 0; i < METHODS.length; ++i) {
                    slab.putInt(flips[i]);
                    slab.putBoolean(positiveWy[i]);
                    for (int k = 0; k < FLIPS_KEPT; ++k) {
                        slab.putDouble(flipTimes[i][k]);
                    }
                }
            }

            @Override
            public void readState(StateSlab slab) {
                elapsedSeconds = slab.getDouble();
                for (int i = 0; i < METHODS.length; ++i) {
                    flips[i] = slab.getInt();
                    positiveWy[i] = slab.getBoolean();
                    for (int k = 0; k < FLIPS_KEPT; ++k) {
                        flipTimes[i][k] = slab.getDouble();
                    }
                }
                // A step back: the views blend from the state put back, not a later one.
                keepPreviousOrientations();
            }
        };
    }

    /** The slide: Euler's equations without torque; each method's flips so far. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        slide.formula().append("I·dω/dt = −ω × (I·ω),   I = diag(1, 2, 3) kg·m²");
        StringBuilder readout = slide.readout().append("flips of ωy:");
        for (int i = 0; i < NAMES.length; ++i) {
            readout.append(i == 0 ? "  " : ",  ").append(NAMES[i]).append(' ').append(flips[i]);
        }
    }
}
