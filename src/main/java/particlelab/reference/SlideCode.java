package particlelab.reference;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Thrust;


/**
 * A free-flight demo's update transcribed from the lecture's slide, as the slide writes it:
 * jME's allocating {@code mult}/{@code add}/{@code divide}/{@code normalize}, each result a new
 * {@code Vector3f} that replaces the particle's position or velocity, and the frame's
 * {@code tpf} as the step. The demos' comparison lane runs it beside the shared integrator
 * (which does the same step in place); the report's {@code LectureStyleParticle} is the same
 * style kept as a benchmark row.
 *
 * <p>Each kind's {@link #listing()} is its {@link #update} line for line, so the HUD can show
 * the code that moves the lane's sphere. The coefficients are read live from the demo's own
 * force objects at each update (that read is the demo's, not the slide's). One instance per
 * particle; not thread-safe.
 */
public abstract class SlideCode {

    /** Position P (in metres; replaced by a new vector every update, as the slide does). */
    public Vector3f position = new Vector3f();
    /** Velocity V (in m/s; replaced by a new vector every update, as the slide does). */
    public Vector3f velocity = new Vector3f();
    /** g as the slide's field has it (in m/s², read from the demo's gravity each update). */
    protected final Vector3f gravity = new Vector3f();
    /** The particle's mass m (in kilograms, &gt;0). */
    protected float mass = 1f;
    private final List<String> lines;

    /**
     * Create a listing.
     *
     * @param lines the update's code lines, in order (not null, copied)
     */
    protected SlideCode(String... lines) {
        this.lines = Collections.unmodifiableList(Arrays.asList(lines.clone()));
    }

    /**
     * Uniform motion's slide: no force, so only the position moves.
     *
     * @return a new listing
     */
    public static SlideCode uniform() {
        return new SlideCode("position = position.add(velocity.mult(tpf));") {
            @Override
            public void update(float tpf) {
                position = position.add(velocity.mult(tpf));
            }
        };
    }

    /**
     * Gravitational pull's slide: {@code velocity.add(gravity.mult(tpf))}, then the position.
     *
     * @param field the demo's gravity, read at each update (not null, not modified)
     * @return a new listing
     */
    public static SlideCode pull(Gravity field) {
        return new SlideCode("velocity = velocity.add(gravity.mult(tpf));",
                "position = position.add(velocity.mult(tpf));") {
            @Override
            public void update(float tpf) {
                field.copyAcceleration(gravity);
                velocity = velocity.add(gravity.mult(tpf));
                position = position.add(velocity.mult(tpf));
            }
        };
    }

    /**
     * The drag slide's linear drag: {@code F = −b·V}, {@code a = g + F/m}.
     *
     * @param field the demo's gravity, read at each update (not null, not modified)
     * @param drag the demo's linear drag, read at each update (not null, not modified)
     * @return a new listing
     */
    public static SlideCode linearDrag(Gravity field, LinearDrag drag) {
        return new SlideCode("Vector3f force = velocity.mult(-b);",
                "Vector3f acceleration = gravity.add(force.divide(mass));",
                "velocity = velocity.add(acceleration.mult(tpf));",
                "position = position.add(velocity.mult(tpf));") {
            @Override
            public void update(float tpf) {
                field.copyAcceleration(gravity);
                float b = drag.getCoefficient();
                Vector3f force = velocity.mult(-b);
                Vector3f acceleration = gravity.add(force.divide(mass));
                velocity = velocity.add(acceleration.mult(tpf));
                position = position.add(velocity.mult(tpf));
            }
        };
    }

    /**
     * The thrust slide: linear drag plus a push k along the sphere's own velocity.
     *
     * @param field the demo's gravity, read at each update (not null, not modified)
     * @param drag the demo's linear drag, read at each update (not null, not modified)
     * @param thrust the demo's thrust, read at each update (not null, not modified)
     * @return a new listing
     */
    public static SlideCode thrust(Gravity field, LinearDrag drag, Thrust thrust) {
        return new SlideCode(
                "Vector3f force = velocity.mult(-b).add(velocity.normalize().mult(k));",
                "Vector3f acceleration = gravity.add(force.divide(mass));",
                "velocity = velocity.add(acceleration.mult(tpf));",
                "position = position.add(velocity.mult(tpf));") {
            @Override
            public void update(float tpf) {
                field.copyAcceleration(gravity);
                float b = drag.getCoefficient();
                float k = thrust.getMagnitude();
                Vector3f force = velocity.mult(-b).add(velocity.normalize().mult(k));
                Vector3f acceleration = gravity.add(force.divide(mass));
                velocity = velocity.add(acceleration.mult(tpf));
                position = position.add(velocity.mult(tpf));
            }
        };
    }

    /**
     * Put the particle at a launch state.
     *
     * @param launchPosition P0 (in metres, not null, copied)
     * @param launchVelocity V0 (in m/s, not null, copied)
     * @param massKg m (in kilograms, &gt;0)
     */
    public final void start(Vector3f launchPosition, Vector3f launchVelocity, float massKg) {
        position = launchPosition.clone();
        velocity = launchVelocity.clone();
        mass = massKg;
    }

    /**
     * Take one frame's step, the slide's way. Allocates, as the slide does.
     *
     * @param tpf the step (in seconds, &gt;0): the frame's tpf on the slide
     */
    public abstract void update(float tpf);

    /**
     * Return the update's code, one line per statement, as the slide shows it.
     *
     * @return the lines (not null, unmodifiable)
     */
    public final List<String> listing() {
        return lines;
    }
}
