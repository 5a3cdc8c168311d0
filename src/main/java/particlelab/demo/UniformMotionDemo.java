package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.physics.ParticleIntegrator;

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

    private DemoParticle sphere;

    /** Create the demo. */
    public UniformMotionDemo() {
        super("Uniform motion");
    }

    @Override
    protected void createScene() {
        // An integrator with no forces: the lecture's "no force, straight line".
        sphere = addParticle("sphere", ColorRGBA.Cyan, START, VELOCITY, 1f,
                new ParticleIntegrator());
        setView(-2f, 32f, 8f, 1f, 5, 0.4f);
        showExactGhosts();
    }

    @Override
    protected void afterStep(float stepSeconds) {
        // Leaving the screen: start over so the demo loops in front of the class. Called
        // from a step, restart() waits until the frame's steps are over, so t starts again
        // from 0 together with P.
        if (sphere.getParticle().position.x > RIGHT_EDGE) {
            restart();
        }
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("No force:  a = 0,  so V = (").append(VELOCITY.x).append(", ")
                .append(VELOCITY.y).append(", 0) m/s stays,  and P = P0 + V*t\n");
    }
}
