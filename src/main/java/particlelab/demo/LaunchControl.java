package particlelab.demo;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.physics.Gravity;

/**
 * The launch and the common coefficients of a demo, as declared parameters: launch speed and
 * angle (in the x-y plane), mass and g, shared by the particles added to it. A demo creates
 * one in its fields, {@link #add}s its particles in {@code createScene}, and declares the
 * parameters it needs with the methods below in {@code declareParameters}.
 *
 * <p>The launch velocity is {@code V0 = speed·(cos θ, sin θ, 0)}, computed in double. At the
 * declared defaults it is the demo's own V0, exactly (so a default run is the run the lecture
 * shows, to the bit, whatever the cosine's round-off).
 */
public final class LaunchControl {

    /** The angle's range (in degrees above the horizontal). */
    public static final float MIN_ANGLE_DEGREES = -30f;
    public static final float MAX_ANGLE_DEGREES = 85f;
    /** The mass's range (in kilograms). */
    public static final float MIN_MASS_KG = 0.1f;
    public static final float MAX_MASS_KG = 10f;
    /** g's range (in m/s²): from a small moon to more than Jupiter's 24.8. */
    public static final float MIN_G = 0.5f;
    public static final float MAX_G = 30f;

    private final List<DemoParticle> particles = new ArrayList<>();
    private final List<Gravity> gravities = new ArrayList<>();
    private final Vector3f defaultVelocity = new Vector3f();
    private final float defaultSpeed;
    private final float defaultAngleDegrees;
    private float speed;
    private float angleDegrees;
    /** Scratch: a particle's launch position (m), the launch velocity (m/s), g (m/s²). */
    private final Vector3f position = new Vector3f();
    private final Vector3f velocity = new Vector3f();
    private final Vector3f acceleration = new Vector3f();

    /**
     * Create the control of a launch velocity in the x-y plane.
     *
     * @param launchVelocity the demo's own V0 (in m/s, finite, not zero, z = 0; copied)
     */
    public LaunchControl(Vector3f launchVelocity) {
        defaultVelocity.set(launchVelocity);
        defaultSpeed = (float) Math.hypot(launchVelocity.x, launchVelocity.y);
        defaultAngleDegrees = (float) Math.toDegrees(Math.atan2(launchVelocity.y,
                launchVelocity.x));
        speed = defaultSpeed;
        angleDegrees = defaultAngleDegrees;
    }

    /**
     * Let a particle be launched with this control's velocity, mass and g.
     *
     * @param particle the particle (not null)
     * @return particle
     */
    public DemoParticle add(DemoParticle particle) {
        particles.add(particle);
        return particle;
    }

    /**
     * Let g set a gravity force.
     *
     * @param gravity a force of the scene (not null)
     * @return gravity
     */
    public Gravity add(Gravity gravity) {
        gravities.add(gravity);
        return gravity;
    }

    /** @return the demo's own launch speed |V0| (in m/s) */
    public float getDefaultSpeed() {
        return defaultSpeed;
    }

    /** @return the demo's own launch angle (in degrees) */
    public float getDefaultAngle() {
        return defaultAngleDegrees;
    }

    /**
     * Copy the launch velocity the particles get at the next launch.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in m/s)
     */
    public Vector3f copyVelocity(Vector3f storeResult) {
        if (speed == defaultSpeed && angleDegrees == defaultAngleDegrees) {
            return storeResult.set(defaultVelocity);
        }
        double radians = Math.toRadians(angleDegrees);
        return storeResult.set((float) (speed * Math.cos(radians)),
                (float) (speed * Math.sin(radians)), 0f);
    }

    /**
     * Declare the whole launch of a projectile demo: speed and angle (at the next launch),
     * mass (at the next launch) and g (live), in the panel's order.
     *
     * @param maxSpeed the largest speed offered (in m/s, &gt;the default)
     * @param speedStep what a key press changes the speed by (in m/s, &gt;0)
     * @param defaultKg the mass at the start (in kg, &gt;0)
     * @return the four declarations (not null)
     */
    public List<DemoParameter> projectileParameters(float maxSpeed, float speedStep,
            float defaultKg) {
        return List.of(speedParameter(maxSpeed, speedStep), angleParameter(),
                massParameter(defaultKg), gravityParameter());
    }

    /**
     * Declare the launch speed, applied at the next launch.
     *
     * @param maxSpeed the largest speed offered (in m/s, &gt;the default)
     * @param step what a key press changes it by (in m/s, &gt;0)
     * @return the declaration (not null)
     */
    public DemoParameter speedParameter(float maxSpeed, float step) {
        return new DemoParameter("speed", "launch speed", "m/s", step, maxSpeed, step,
                defaultSpeed, 2, DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    speed = value;
                    applyLaunch();
                });
    }

    /**
     * Declare the launch angle above the horizontal, applied at the next launch.
     *
     * @return the declaration (not null)
     */
    public DemoParameter angleParameter() {
        return new DemoParameter("angle", "launch angle", "deg", MIN_ANGLE_DEGREES,
                MAX_ANGLE_DEGREES, 1f, defaultAngleDegrees, 1,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    angleDegrees = value;
                    applyLaunch();
                });
    }

    /**
     * Declare the particles' mass, applied at the next launch.
     *
     * @param defaultKg the mass at the start (in kg, in the range)
     * @return the declaration (not null)
     */
    public DemoParameter massParameter(float defaultKg) {
        return new DemoParameter("mass", "mass", "kg", MIN_MASS_KG, MAX_MASS_KG, 0.1f,
                defaultKg, 2, DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    for (int i = 0; i < particles.size(); ++i) {
                        particles.get(i).getParticle().setMass(value);
                    }
                });
    }

    /**
     * Declare g, pointing down, applied at once to every gravity force added.
     *
     * @return the declaration (not null)
     */
    public DemoParameter gravityParameter() {
        return gravityParameter(MIN_G);
    }

    /**
     * Declare g, pointing down, from a smallest value of the demo's choosing: 0 lets the
     * pull demo switch gravity off (Newton's first law). Never below 0: g points down.
     *
     * @param minG the smallest g offered (in m/s², from 0 to {@link #MIN_G})
     * @return the declaration (not null)
     */
    public DemoParameter gravityParameter(float minG) {
        if (!(minG >= 0f && minG <= MIN_G)) {
            throw new IllegalArgumentException("the smallest g (m/s²) must be from 0 to "
                    + MIN_G + ", but was " + minG);
        }
        return new DemoParameter("g", "gravity", "m/s²", minG, MAX_G, 0.1f,
                Gravity.STANDARD_G, 2, DemoParameter.Applies.LIVE, value -> {
                    acceleration.set(0f, -value, 0f);
                    for (int i = 0; i < gravities.size(); ++i) {
                        gravities.get(i).setAcceleration(acceleration);
                    }
                });
    }

    /**
     * Declare the drag of the launch position: the sphere goes under the mouse and every
     * particle of this launch moves with it (paused only, see
     * {@link Draggable#launchPosition}).
     *
     * @param what the particles as the help names them, e.g. "a sphere" (not null)
     * @return the declaration (not null)
     */
    public Draggable dragPosition(String what) {
        return Draggable.launchPosition(what, particles);
    }

    /**
     * Declare the drag of the launch velocity by an arrow's tip: the tip under the mouse
     * gives {@code V0 = (tip − P0)/T}, written into the speed and angle parameters (so the
     * panel, the equations and the kept shots' legend show it), each clamped to its range;
     * it applies at once, the scene starting again at t = 0. Paused only. Declare the speed
     * and angle parameters too.
     *
     * @param what the particles as the help names them (not null)
     * @param parameters the demo's parameters, with "speed" and "angle" (not null)
     * @return the declaration (not null)
     */
    public Draggable dragVelocity(String what, DemoParameters parameters) {
        return new Draggable(what, Draggable.Grip.ARROW_TIP, Draggable.Effect.LAUNCH,
                particles, "launch V0" + Draggable.ofAll(Draggable.countShown(particles))
                        + " = speed, angle",
                Draggable.PAUSED_NOTE, false,
                (particle, dragged) -> {
                    DemoParameter speedParameter = parameters.get(parameters.indexOf("speed"));
                    DemoParameter angleParameter = parameters.get(parameters.indexOf("angle"));
                    float newSpeed = (float) Math.hypot(dragged.x, dragged.y);
                    float newAngle = (float) Math.toDegrees(Math.atan2(dragged.y, dragged.x));
                    parameters.set("speed", clamp(newSpeed, speedParameter));
                    parameters.set("angle", clamp(newAngle, angleParameter));
                });
    }

    /**
     * Write the launch as the HUD's equations show it: "m = 1 kg,  V0 = (10, 10, 0) m/s",
     * and g when it is not the standard 9.8 m/s² (the line stays as short as the lecture's).
     * Uses the values in the scene.
     *
     * @param text where to append (not null, modified)
     * @param parameters the demo's parameters, with "mass" and "g" declared (not null)
     * @return text
     */
    public StringBuilder appendLaunch(StringBuilder text, DemoParameters parameters) {
        float g = parameters.getValueInScene(parameters.indexOf("g"));
        text.append("m = ");
        DemoParameter.appendShort(text, parameters.getValueInScene(parameters.indexOf("mass")),
                2).append(" kg,  ");
        if (g != Gravity.STANDARD_G) {
            DemoParameter.appendShort(text.append("g = "), g, 2).append(" m/s²,  ");
        }
        copyVelocity(velocity);
        text.append("V0 = (");
        DemoParameter.appendShort(text, velocity.x, 2).append(", ");
        return DemoParameter.appendShort(text, velocity.y, 2).append(", 0) m/s");
    }

    /** @return value clamped to the parameter's range */
    private static float clamp(float value, DemoParameter parameter) {
        return Math.max(parameter.getMin(), Math.min(parameter.getMax(), value));
    }

    /** Give every particle the launch velocity, from its own launch position. */
    private void applyLaunch() {
        copyVelocity(velocity);
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            particle.copyLaunchPosition(position);
            particle.setLaunch(position, velocity);
        }
    }
}
