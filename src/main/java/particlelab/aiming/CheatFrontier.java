package particlelab.aiming;

import com.jme3.math.Vector3f;
import particlelab.collision.Plane;
import particlelab.collision.Surface;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * The cheat's frontier: four ways a game can shoot at a disc of radius r at distance d, level
 * with the gun, each cheaper or more accurate than the next ({@code g} along −y, the gun at
 * the origin, the disc's centre at {@code (d, 0, 0)}, the muzzle speed v, the step h).
 *
 * <ol>
 * <li>{@link Way#RAY}, the instant ray (hitscan): the hit is found at {@code t = 0} on the
 * straight aim line.</li>
 * <li>{@link Way#STRAIGHT}, a straight-line bullet with travel time: stepped along the aim
 * line at v with no drop ("consider it to travel along a straight line"), so it arrives at
 * {@code t = d/v}, still on the centre.</li>
 * <li>{@link Way#CORRECTED}, the drop-corrected straight line ("adjust its position if
 * necessary"): the aim raised by the closed-form drop {@code D = ½·g·(d/v)²}, the same
 * straight-line bullet along the raised line, {@code tan θ = D/d}.</li>
 * <li>{@link Way#STEPPED}, the stepped projectile: the shared integrator, level aim, each
 * step's segment swept against the disc's plane ({@link Hitscan#fireAtDisc}).</li>
 * </ol>
 *
 * <p>Each way's <b>miss</b> is where a real bullet crosses {@code x = d} when the gun aims as
 * that way says, relative to the centre (+ above): the exact parabola for the three
 * straight-line ways (they do not move a bullet under gravity, they choose the aim), the
 * stepped bullet itself for the fourth (it is the bullet). So the ray and the straight line
 * both miss by {@code −D}; the corrected aim, fired at v along θ, takes
 * {@code T = d/(v·cos θ)} and crosses at {@code d·tan θ − ½·g·T² = D − D/cos²θ =
 * −D·tan²θ = −D³/d²}: second order in the slope {@code D/d}; the stepped bullet misses by
 * {@link Hitscan#steppedDrop}, about {@code D + ½·g·h·t}.
 *
 * <p>The shots ({@link #shoot}) are the per-shot work each way does in a game, allocation-free,
 * for timing: one ray test, or one straight step and one swept plane test per step, or one
 * integrator step and one swept test per step.
 */
public final class CheatFrontier {

    /** The four ways to shoot, cheapest first. */
    public enum Way {
        /** The instant ray (hitscan). */
        RAY,
        /** A straight-line bullet with travel time, no drop. */
        STRAIGHT,
        /** The straight line with the aim raised by the closed-form drop. */
        CORRECTED,
        /** The projectile stepped by the shared integrator. */
        STEPPED
    }

    /** The ways in ordinal order, without the copy {@code values()} makes. */
    private static final Way[] WAYS = Way.values();
    /** A shot that has not reached the plane after this many steps gives up. */
    private static final int MAX_STEPS = 100_000;

    /** g, d and r (in m/s², metres, metres), fixed for the frontier's life. */
    private final float gravity;
    private final float distance;
    private final float radiusMetres;
    /** v and h (in m/s, seconds), changed by {@link #reset}. */
    private float speed;
    private float stepSeconds;
    private final Hitscan stepped;
    private final TargetImpact impact = new TargetImpact();
    /** The disc's plane {@code x = d}, its front facing the gun. */
    private final Plane face;
    /** The straight line's direction (unit) and velocity (m/s), level or raised. */
    private final Vector3f direction = new Vector3f();
    private final Vector3f lineVelocity = new Vector3f();
    /** Scratch for the shots: the bullet's position before and after a step (m). */
    private final Vector3f previous = new Vector3f();
    private final Vector3f position = new Vector3f();
    private final Vector3f normal = new Vector3f();
    /** Each way's miss (m), hit time (s) and steps, by ordinal. */
    private final double[] miss = new double[WAYS.length];
    private final double[] hitSeconds = new double[WAYS.length];
    private final int[] steps = new int[WAYS.length];
    /** The closed-form drop D and the corrected aim's slope tan θ. */
    private double drop;
    private double raisedSlope;

    /**
     * Work out the four ways for one shot.
     *
     * @param gravity g, pointing down (in m/s², finite, &gt;0)
     * @param distance d (in metres, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &gt;0)
     * @param speed v, the muzzle speed (in m/s, finite, &gt;0)
     * @param stepSeconds h, the step of the stepped ways (in seconds, finite, &gt;0)
     */
    public CheatFrontier(float gravity, float distance, float radiusMetres, float speed,
            float stepSeconds) {
        this.gravity = Validate.positive(gravity, "gravity g (m/s^2)");
        this.distance = Validate.positive(distance, "distance d (m)");
        this.radiusMetres = Validate.positive(radiusMetres, "target radius r (m)");
        Gravity field = new Gravity();
        field.setAcceleration(new Vector3f(0f, -gravity, 0f));
        stepped = new Hitscan(new ParticleIntegrator(field), stepSeconds, MAX_STEPS);
        face = new Plane(new Vector3f(-1f, 0f, 0f), -distance);
        reset(speed, stepSeconds);
    }

    /**
     * Work out the four ways again, in place, for another muzzle speed or step (the same
     * gravity, distance and disc): a demo that refires at a changing h reuses one frontier.
     * Allocation-free.
     *
     * @param newSpeed v, the muzzle speed (in m/s, finite, &gt;0)
     * @param newStepSeconds h, the step of the stepped ways (in seconds, finite, &gt;0)
     */
    public void reset(float newSpeed, float newStepSeconds) {
        // Both checked before either is kept, so a bad value leaves the frontier as it was.
        Validate.positive(newSpeed, "speed v (m/s)");
        Validate.positive(newStepSeconds, "step h (s)");
        speed = newSpeed;
        stepSeconds = newStepSeconds;
        stepped.setStepSeconds(newStepSeconds);
        drop = Hitscan.formulaDrop(gravity, distance, speed);
        raisedSlope = drop / distance;
        double levelTime = distance / (double) speed;
        // The ray: found at once; a real bullet on its level aim falls D by x = d.
        miss[Way.RAY.ordinal()] = -drop;
        hitSeconds[Way.RAY.ordinal()] = 0.0;
        steps[Way.RAY.ordinal()] = 0;
        // The straight line: arrives at d/v on the centre; a real bullet is D lower.
        shoot(Way.STRAIGHT);
        miss[Way.STRAIGHT.ordinal()] = -drop;
        // The corrected aim: a real bullet on it crosses at d·tanθ − ½·g·(d/(v·cosθ))².
        shoot(Way.CORRECTED);
        double cosine = 1.0 / Math.sqrt(1.0 + raisedSlope * raisedSlope);
        double raisedTime = levelTime / cosine;
        miss[Way.CORRECTED.ordinal()] = distance * raisedSlope
                - 0.5 * gravity * raisedTime * raisedTime;
        // The stepped projectile is the bullet: its own crossing.
        shoot(Way.STEPPED);
    }

    /**
     * Return the muzzle speed the ways were worked out for.
     *
     * @return v (in m/s)
     */
    public float getSpeed() {
        return speed;
    }

    /**
     * Return the step the stepped ways were worked out for.
     *
     * @return h (in seconds)
     */
    public float getStepSeconds() {
        return stepSeconds;
    }

    /**
     * Return the closed-form drop the straight line ignores, {@code D = ½·g·(d/v)²}.
     *
     * @return D (in metres, &gt;0)
     */
    public double getDrop() {
        return drop;
    }

    /**
     * Return one way's miss: where a real bullet aimed as the way says crosses {@code x = d},
     * relative to the centre (see the class's Javadoc).
     *
     * @param way the way (not null)
     * @return the miss (in metres, + above the centre; NaN if the stepped bullet never got
     *     there)
     */
    public double getMiss(Way way) {
        return miss[Validate.notNull(way, "way").ordinal()];
    }

    /**
     * Return one way's hit time: when the way finds its bullet at {@code x = d}.
     *
     * @param way the way (not null)
     * @return the time after the shot (in seconds; 0 for the ray)
     */
    public double getHitSeconds(Way way) {
        return hitSeconds[Validate.notNull(way, "way").ordinal()];
    }

    /**
     * Return how many steps one way's shot takes.
     *
     * @param way the way (not null)
     * @return the steps (0 for the ray)
     */
    public int getSteps(Way way) {
        return steps[Validate.notNull(way, "way").ordinal()];
    }

    /**
     * Test whether a way's miss is within the disc's radius.
     *
     * @param way the way (not null)
     * @return true on a hit
     */
    public boolean hits(Way way) {
        return Math.abs(miss[Validate.notNull(way, "way").ordinal()]) <= radiusMetres;
    }

    /**
     * Do one way's per-shot work, as a game would, and record its hit time and steps:
     * allocation-free, for timing.
     *
     * @param way the way (not null)
     * @return the height where the way's own bullet meets the plane {@code x = d} (in metres,
     *     the centre at 0; NaN if it never gets there)
     */
    public double shoot(Way way) {
        switch (Validate.notNull(way, "way")) {
            case RAY:
                return shootRay();
            case STRAIGHT:
                return shootLine(way, 0.0);
            case CORRECTED:
                return shootLine(way, raisedSlope);
            case STEPPED:
                return shootStepped();
            default:
                throw new IllegalArgumentException("way must be one of the four, but was "
                        + way);
        }
    }

    /** The ray from the gun along the level aim, met by the disc's plane at once. */
    private double shootRay() {
        previous.zero();
        position.set(distance + radiusMetres, 0f, 0f);
        double fraction = face.sweep(previous, position, 0f, normal);
        return fraction == Surface.NO_HIT ? Double.NaN
                : previous.y + fraction * ((double) position.y - previous.y);
    }

    /** A bullet stepped along a straight line of slope {@code slope}, no gravity. */
    private double shootLine(Way way, double slope) {
        double cosine = 1.0 / Math.sqrt(1.0 + slope * slope);
        direction.set((float) cosine, (float) (slope * cosine), 0f);
        direction.mult(speed, lineVelocity);
        position.zero();
        for (int step = 1; step <= MAX_STEPS; ++step) {
            previous.set(position);
            position.scaleAdd(stepSeconds, lineVelocity, position);
            double fraction = face.sweep(previous, position, 0f, normal);
            if (fraction != Surface.NO_HIT) {
                int index = way.ordinal();
                hitSeconds[index] = (step - 1 + fraction) * stepSeconds;
                steps[index] = step;
                return previous.y + fraction * ((double) position.y - previous.y);
            }
        }
        hitSeconds[way.ordinal()] = Double.NaN;
        steps[way.ordinal()] = MAX_STEPS;
        return Double.NaN;
    }

    /** The shared integrator's projectile, level aim, swept at the disc. */
    private double shootStepped() {
        int index = Way.STEPPED.ordinal();
        if (stepped.fireAtDisc(speed, distance, radiusMetres, impact)) {
            miss[index] = impact.getY();
            hitSeconds[index] = impact.getTimeSeconds();
        } else {
            miss[index] = Double.NaN;
            hitSeconds[index] = Double.NaN;
        }
        steps[index] = impact.getSteps();
        return miss[index];
    }
}
