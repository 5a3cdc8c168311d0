package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationIntegrator;
import particlelab.view.BoxView;
import particlelab.view.ParticleView;
import particlelab.view.TextFormat;
import particlelab.view.Trail;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * Spin and throw: rotation combined with translation. A box is thrown with {@code V0} and
 * spun with {@code ω0} about its body z axis (a principal axis, pointing at the camera).
 * Builds upon gravitational pull (the centre) and the rotation demo (the turning).
 *
 * <p>The lecture's advice, "keep it simple: separate translation and rotation", is what each
 * step does: the shared particle integrator moves the centre exactly as it moves a ball
 * ({@code V += h·g, P += h·V}), then the rotation integrator turns the box about its centre
 * ({@code ω += h·τ/I}, then R turned by the new ω); a corner is at {@code P + R·b}.
 *
 * <p>For a constant torque τ about the same principal axis the closed form is the parabola of
 * the centre plus a turning offset: {@code P(t) = P0 + V0·t + ½·g·t²},
 * {@code θ(t) = ω0·t + ½·(τ/I)·t²}, corner = {@code P(t) + Rz(θ(t))·b}; it is drawn as the
 * faint trail beside the stepped corner's. J cycles the torque (none, +τ, −τ) and throws
 * again; B switches linear drag on the centre (the closed form then has the drag's
 * exponential, and the spin is not affected: drag through the centre has no torque).
 *
 * <p>What to watch for: the corner's loops ride on the centre's parabola. The stepped angle
 * runs ahead of the formula by {@code ½·(τ/I)·h·t} (the rotation step uses the new ω, as the
 * particle step uses the new V), the angular twin of the particle landing {@code vx·h} short;
 * both gaps shrink with h.
 */
public final class SpinThrowDemo extends DemoState {

    /** The box's mass (kg) and sides along its body x, y, z (m). */
    public static final float MASS_KG = 1f;
    public static final Vector3f SIDES = new Vector3f(0.9f, 0.5f, 0.3f);
    /** Launch: the centre's position and velocity, the spin about body z (rad/s). */
    public static final Vector3f LAUNCH_POSITION = new Vector3f(0f, 1.5f, 0f);
    public static final Vector3f LAUNCH_VELOCITY = new Vector3f(6f, 9f, 0f);
    public static final float SPIN = 10f;
    /** The torque the key applies about body z (N·m). */
    public static final float TORQUE = 0.2f;
    /** The corner whose trail is drawn, in body coordinates (m). */
    public static final Vector3f CORNER = new Vector3f(SIDES).multLocal(0.5f);
    private static final int TRAIL_POINTS = 600;
    private static final float TRAIL_WIDTH = 0.08f;
    private static final float[] TORQUES = {0f, TORQUE, -TORQUE};
    private static final Vector3f GRAVITY = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    /** The linear drag the B key switches on (N·s/m). */
    public static final float DRAG_B = 0.3f;

    /** Linear drag on the centre, b = 0 while switched off. */
    private final LinearDrag drag = new LinearDrag(0f);

    private final RotationIntegrator rotation = new RotationIntegrator(
            RotationIntegrator.Orientation.EXACT, RotationIntegrator.Angular.EXPLICIT, true);
    private final Inertia inertia = Inertia.box(MASS_KG, SIDES.x, SIDES.y, SIDES.z);
    private final Vector3f halfExtents = new Vector3f(SIDES).multLocal(0.5f);
    private final Vector3f corner = new Vector3f();
    private final Vector3f formulaCorner = new Vector3f();
    private final Vector3f formulaCentre = new Vector3f();
    /** The box's R as the last step started, for the view to draw between steps. */
    private final Matrix3f previousOrientation = new Matrix3f();
    /** Scratch: the centre as the last step started (m). */
    private final Vector3f previousCentre = new Vector3f();
    /** The points each trail was given since the last restart (one per step moved). */
    private long trailPoints;
    private DemoParticle centre;
    private RigidBody body;
    private BoxView box;
    /** The view's listener: after each step the box's trails take the new points. */
    private final StepListener trailWriter = new StepListener() {
        @Override
        public void afterStep(World stepping, float stepSeconds) {
            if (cornerTrail != null && centre.wasSteppedThisStep()) {
                centreTrail.add(body.getParticle().position);
                cornerTrail.add(body.bodyToWorld(CORNER, corner));
                formulaTrail.add(formulaCorner(spinSeconds, formulaCorner));
                ++trailPoints;
            }
        }
    };
    private Trail centreTrail;
    private Trail cornerTrail;
    private Trail formulaTrail;
    private int torqueChoice;
    /** The angle turned about z, unwrapped from R, and R's last atan2 angle (rad). */
    private double measuredAngle;
    private double lastAtan;
    /** How long the box has turned since the throw (s): the clock's t until it lands. */
    private double spinSeconds;
    private KeyBinding torqueKey;

    /** Create the demo. */
    public SpinThrowDemo() {
        super("Spin and throw");
    }

    /**
     * Access the rigid body (its centre is the demo's particle).
     *
     * @return the live body (not null after initialisation)
     */
    public RigidBody getBody() {
        return body;
    }

    /**
     * Access the box's view.
     *
     * @return the live view (null before the window)
     */
    public BoxView getBoxView() {
        return box;
    }

    /**
     * Return the torque now applied about z.
     *
     * @return τ (in N·m)
     */
    public float getTorque() {
        return TORQUES[torqueChoice];
    }

    /**
     * Choose the torque about z and throw again.
     *
     * @param choice 0 for none, 1 for +{@link #TORQUE}, 2 for −{@link #TORQUE}
     */
    public void setTorqueChoice(int choice) {
        if (choice < 0 || choice >= TORQUES.length) {
            throw new IllegalArgumentException("torque choice must be 0, 1 or 2, but was "
                    + choice);
        }
        torqueChoice = choice;
        restart();
    }

    /**
     * Switch linear drag {@code b = DRAG_B} on the centre on or off, and throw again.
     *
     * @param on true for drag
     */
    public void setDrag(boolean on) {
        drag.setCoefficient(on ? DRAG_B : 0f);
        refreshEquations();
        restart();
    }

    /**
     * Return the angle the box has turned about z since the throw, read from R (unwrapped).
     *
     * @return θ (in radians)
     */
    public double getMeasuredAngle() {
        return measuredAngle;
    }

    /**
     * Return how long the box has turned since the throw: the clock's t while it flies (the
     * landing step moves the centre only part of h and stops the spin).
     *
     * @return t (in seconds, &ge;0)
     */
    public double getSpinSeconds() {
        return spinSeconds;
    }

    /**
     * Calculate the closed form's angle {@code θ(t) = ω0·t + ½·(τ/I)·t²}.
     *
     * @param seconds t (in seconds)
     * @return θ (in radians)
     */
    public double formulaAngle(double seconds) {
        return SPIN * seconds + 0.5 * getTorque() / inertia.getMoment(2) * seconds * seconds;
    }

    /**
     * Copy the closed form's corner at time t, {@code P0 + V0·t + ½·g·t² + Rz(θ(t))·b}.
     *
     * @param seconds t (in seconds)
     * @param storeResult storage for the point (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f formulaCorner(double seconds, Vector3f storeResult) {
        double theta = formulaAngle(seconds);
        double cos = Math.cos(theta);
        double sin = Math.sin(theta);
        return storeResult.set(
                (float) (centreFormula(LAUNCH_POSITION.x, LAUNCH_VELOCITY.x, GRAVITY.x, seconds)
                        + cos * CORNER.x - sin * CORNER.y),
                (float) (centreFormula(LAUNCH_POSITION.y, LAUNCH_VELOCITY.y, GRAVITY.y, seconds)
                        + sin * CORNER.x + cos * CORNER.y),
                CORNER.z);
    }

    @Override
    protected void createScene() {
        centre = addParticle("centre", new ColorRGBA(1f, 0.85f, 0.35f, 1f), LAUNCH_POSITION,
                LAUNCH_VELOCITY, MASS_KG, new ParticleIntegrator(new Gravity(), drag))
                .stopAtGround();
        // The rigid body shares the demo particle: the world steps the translation (the
        // particle's step) and then the rotation, in the same step.
        body = new RigidBody(centre.getParticle(), inertia);
        centre.getBody().setRotation(body, rotation);
        resetRotation();
        // The sphere's radius is the box's half diagonal, so the centre's label keeps clear
        // of the turning box; the sphere itself is hidden inside the box (initialize).
        setView(-1f, 14f, 7f, 1f, 5, 0.5f * SIDES.length());
        addStateRecord(spinState());
    }

    @Override
    protected void declareKeys() {
        torqueKey = bindKey(KeyInput.KEY_J, "J", "torque about z: none -> +" + TORQUE
                + " N·m -> -" + TORQUE + " N·m (throws again)",
                () -> setTorqueChoice((torqueChoice + 1) % TORQUES.length));
        bindKey(KeyInput.KEY_B, "B", "linear drag on the centre: off <-> b = " + DRAG_B
                + " N·s/m (throws again)", this::toggleDrag);
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("centre: V += h·(g − (b/m)·V),  P += h·V,  m = ");
        TextFormat.appendFixed(text, MASS_KG, 1).append(" kg,  b = ");
        TextFormat.appendFixed(text, drag.getCoefficient(), 1).append(" N·s/m\n");
        text.append("spin: ω += h·τ/I_z,  R = exp(h[ω]×)·R,  I_z = m(");
        TextFormat.appendFixed(text, SIDES.x, 1).append("² + ");
        TextFormat.appendFixed(text, SIDES.y, 1).append("²)/12 = ");
        TextFormat.appendFixed(text, inertia.getMoment(2), 4).append(" kg·m²;  corner = P + R·");
        TextFormat.appendVector(text, CORNER, 2).append(" m\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        double t = spinSeconds;
        text.append("τ = ");
        TextFormat.appendFixed(text, getTorque(), 2).append(" N·m about z (")
                .append(torqueKey.getKeyLabel()).append("),  θ stepped = ");
        TextFormat.appendFixed(text, measuredAngle, 4).append(" rad,  formula ω0·t + ½(τ/I)t² = ");
        double formula = formulaAngle(t);
        TextFormat.appendFixed(text, formula, 4).append(" rad,  ahead by ");
        TextFormat.appendFixed(text, measuredAngle - formula, 4).append(" (½(τ/I)·h·t = ");
        TextFormat.appendFixed(text, 0.5 * getTorque() / inertia.getMoment(2)
                * getClock().getStepSeconds() * t, 4).append(")\n");
        text.append("corner: stepped (bright) vs closed form (faint), apart by ");
        formulaCorner(t, formulaCorner);
        body.bodyToWorld(CORNER, corner);
        TextFormat.appendFixed(text, corner.distance(formulaCorner), 3).append(" m\n");
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        // What the view blends from: the box as this step starts.
        previousOrientation.set(body.orientation);
    }

    @Override
    protected void afterStep(float stepSeconds) {
        if (!centre.wasSteppedThisStep()) {
            return;
        }
        // The world turned the box with its translation; this only measures the turn.
        double atan = Math.atan2(body.orientation.get(1, 0), body.orientation.get(0, 0));
        double turn = atan - lastAtan;
        measuredAngle += turn - 2.0 * Math.PI * Math.rint(turn / (2.0 * Math.PI));
        lastAtan = atan;
        spinSeconds += stepSeconds;
    }

    @Override
    protected void afterFrame() {
        updateViews();
    }

    @Override
    protected void onRestart() {
        resetRotation();
        if (cornerTrail != null) {
            centreTrail.clear();
            cornerTrail.clear();
            formulaTrail.clear();
            centreTrail.add(body.getParticle().position);
            cornerTrail.add(body.bodyToWorld(CORNER, corner));
            formulaTrail.add(formulaCorner(0.0, formulaCorner));
        }
        trailPoints = 0L;
        updateViews();
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        Material unshaded = new Material(app.getAssetManager(),
                "Common/MatDefs/Misc/Unshaded.j3md");
        // The box is the body now: hide the centre's sphere, and draw its trail thinner
        // (the shared one is as wide as half the sphere, here the box's half diagonal). The
        // label stays, placed clear of the box.
        ParticleView centreView = getWindow().getView(centre);
        centreView.getNode().getChild(centre.getLabel() + " sphere")
                .setCullHint(Spatial.CullHint.Always);
        centreView.getNode().detachChild(centreView.getTrail().getGeometry());
        centreTrail = new Trail("centre trail", TRAIL_POINTS, TRAIL_WIDTH,
                centre.getColor(), unshaded);
        cornerTrail = new Trail("corner trail", TRAIL_POINTS, TRAIL_WIDTH,
                new ColorRGBA(1f, 0.4f, 0.3f, 1f), unshaded);
        formulaTrail = new Trail("closed-form corner trail", TRAIL_POINTS, 2f * TRAIL_WIDTH,
                new ColorRGBA(1f, 1f, 1f, 0.3f), unshaded);
        box = new BoxView(app.getAssetManager(), "thrown box", halfExtents,
                new ColorRGBA(0.35f, 0.8f, 1f, 1f));
        getSceneNode().attachChild(centreTrail.getGeometry());
        getSceneNode().attachChild(formulaTrail.getGeometry());
        getSceneNode().attachChild(cornerTrail.getGeometry());
        getSceneNode().attachChild(box.getGeometry());
        getWorld().addStepListener(trailWriter);
        onRestart();
    }

    @Override
    protected void cleanup(Application app) {
        getWorld().removeStepListener(trailWriter);
        super.cleanup(app);
    }

    /**
     * The centre's closed form along one axis: {@code p0 + v0·t + ½·g·t²} without drag, and
     * with linear drag ({@code k = b/m}, terminal velocity {@code g/k})
     * {@code p0 + (g/k)·t + (v0 − g/k)·(1 − e^(−k·t))/k}.
     */
    private double centreFormula(double p0, double v0, double g, double seconds) {
        double k = drag.getCoefficient() / MASS_KG;
        if (k == 0.0) {
            return p0 + v0 * seconds + 0.5 * g * seconds * seconds;
        }
        double terminal = g / k;
        return p0 + terminal * seconds + (v0 - terminal) * -Math.expm1(-k * seconds) / k;
    }

    private void toggleDrag() {
        setDrag(drag.getCoefficient() == 0f);
    }

    private void resetRotation() {
        body.orientation.loadIdentity();
        previousOrientation.loadIdentity();
        body.angularVelocity.set(0f, 0f, SPIN);
        body.torque.set(0f, 0f, TORQUES[torqueChoice]);
        measuredAngle = 0.0;
        lastAtan = 0.0;
        spinSeconds = 0.0;
    }

    /**
     * Draw the box between its last two states, at this frame's blend (F6; 1 when paused,
     * replaying or drawing raw steps), and the trails.
     */
    private void updateViews() {
        if (box != null) {
            box.update(previousOrientation, centre.getBody().copyPreviousPosition(
                    previousCentre), body.orientation, body.getParticle().position,
                    getWindow().getDrawBlend());
            centreTrail.refresh();
            cornerTrail.refresh();
            formulaTrail.refresh();
        }
    }

    /**
     * Walk the trails to a recorded state's count of points: a step undone takes its point
     * off each, a step redone adds the points of the state put back (the same ones the step
     * had added).
     */
    private void walkTrails(long points) {
        if (cornerTrail != null) {
            for (long n = points; n < trailPoints && centreTrail.size() > 1; ++n) {
                centreTrail.removeNewest();
                cornerTrail.removeNewest();
                formulaTrail.removeNewest();
            }
            for (long n = trailPoints; n < points; ++n) {
                centreTrail.add(body.getParticle().position);
                cornerTrail.add(body.bodyToWorld(CORNER, corner));
                formulaTrail.add(formulaCorner(spinSeconds, formulaCorner));
            }
        }
        trailPoints = points;
    }

    /**
     * The demo's own state, for the ring: the angle measured so far and for how long, and the
     * trails' count of points (so a step back takes the later points off).
     */
    private StateRecord spinState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 4 * 2;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putDouble(measuredAngle);
                slab.putDouble(lastAtan);
                slab.putDouble(spinSeconds);
                slab.putLong(trailPoints);
            }

            @Override
            public void readState(StateSlab slab) {
                measuredAngle = slab.getDouble();
                lastAtan = slab.getDouble();
                spinSeconds = slab.getDouble();
                walkTrails(slab.getLong());
                previousOrientation.set(body.orientation);
            }
        };
    }

    /** The slide: the spin's Euler step under τ; the stepped angle against the closed form. */
    @Override
    protected void writePresentation(Presentation slide) {
        StringBuilder formula = slide.formula().append("ω += h·τ/I_z,   τ = ");
        TextFormat.appendFixed(formula, getTorque(), 2).append(" N·m,  I_z = ");
        TextFormat.appendFixed(formula, inertia.getMoment(2), 4).append(" kg·m²");
        StringBuilder readout = slide.readout().append("θ stepped ");
        TextFormat.appendFixed(readout, measuredAngle, 4).append(" rad,  formula ");
        TextFormat.appendFixed(readout, formulaAngle(spinSeconds), 4).append(" rad");
    }
}
