package particlelab.lecture;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.reference.SlideCode;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.WhatIfPart;
import particlelab.demo.Presentation;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.TextFormat;

/**
 * Demo 1, uniform motion: no force at all, so {@code a = 0} and the Euler step only moves the
 * sphere, {@code P ← P + h·V}, by the same distance every step.
 *
 * <p>What to watch for: the trail is a straight line and {@code |V|} never changes; the
 * position grows linearly, {@code P = P0 + V·t}, exactly (no error at any h, raw tpf or fixed,
 * because the velocity is constant). Everything else builds upon this.
 */
public final class UniformMotionDemo extends DemoState {

    /** Where the sphere starts (m) and how fast it moves (m/s). */
    private static final Vector3f START = new Vector3f(0f, 1f, 0f);
    private static final Vector3f VELOCITY = new Vector3f(4f, 1.2f, 0f);
    /** The sphere starts over when it passes this x (m). */
    private static final float RIGHT_EDGE = 30f;
    /** ... or leaves above or below (m): a steep or downward launch never reaches x = 30. */
    private static final float TOP_EDGE = 11f;
    private static final float BOTTOM_EDGE = -1f;
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 12f;
    private static final float SPEED_STEP = 0.25f;
    /** The spheres' drawn radius (m). */
    private static final float SPHERE_RADIUS = 0.4f;

    /** The launch speed and angle, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(VELOCITY);
    /** Scratch: the launch velocity as printed (m/s). */
    private final Vector3f shownVelocity = new Vector3f();
    /** The comparison lane beside the sphere: off, the slide's code, a report stepper. */
    private final ComparisonLane lane = addPart(new ComparisonLane(SlideCode::uniform,
            SPHERE_RADIUS));
    /** The derivative lens on the followed sphere (key O, {@code --set lens=on}). */
    private final LensPart lens = addPart(new LensPart(SPHERE_RADIUS));
    /** What-if forks (Insert, Delete, J): as recorded, h = 1/30 s. */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(UniformMotionDemo::new,
            new String[] {null, "h"}, new float[] {0f, 1f / 30f}, 0f));
    private DemoParticle sphere;

    /** Create the demo. */
    public UniformMotionDemo() {
        super("Uniform motion");
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
        // An integrator with no forces: the lecture's "no force, straight line".
        sphere = launch.add(addParticle("sphere", ColorRGBA.Cyan, START, VELOCITY, 1f,
                new ParticleIntegrator()));
        lane.follow(launch, sphere);
        lens.follow(sphere);
        // Tall enough for the default launch: y = 1 + 1.2·30/4 = 10 m at the right edge.
        setView(-2f, 32f, 10.5f, 1f, 5, SPHERE_RADIUS);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        // No force acts, so neither mass nor g changes anything: only the launch.
        declareParameter(launch.speedParameter(MAX_SPEED, SPEED_STEP));
        declareParameter(launch.angleParameter());
    }

    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("the sphere"));
        declareDraggable(launch.dragVelocity("the sphere", getParameters()));
    }

    @Override
    protected void afterStep(float stepSeconds) {
        // Leaving the screen: start over so the demo loops in front of the class. Called
        // from a step, restart() waits until the frame's steps are over, so t starts again
        // from 0 together with P.
        Vector3f position = sphere.getParticle().position;
        if (position.x > RIGHT_EDGE || position.y > TOP_EDGE || position.y < BOTTOM_EDGE) {
            restart();
        }
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        launch.copyVelocity(shownVelocity);
        text.append("No force:  a = 0,  so V = (");
        DemoParameter.appendShort(text, shownVelocity.x, 2).append(", ");
        DemoParameter.appendShort(text, shownVelocity.y, 2)
                .append(", 0) m/s stays,  and P = P0 + V·t\n");
    }

    /** The slide: no force, so V stays; where the sphere is now. */
    @Override
    protected void writePresentation(Presentation slide) {
        Particle particle = sphere.getParticle();
        TextFormat.appendVector(slide.formula().append("a = 0,  so V = "), particle.velocity, 2)
                .append(" m/s stays:  P = P0 + V·t");
        StringBuilder readout = slide.readout().append("P = ");
        TextFormat.appendVector(readout, particle.position, 2).append(" m   at t = ");
        TextFormat.appendFixed(readout, getClock().getSimulatedSeconds(), 2).append(" s");
    }
}
