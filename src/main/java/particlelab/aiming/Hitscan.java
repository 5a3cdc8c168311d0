package particlelab.aiming;

import com.jme3.math.Vector3f;
import particlelab.collision.Plane;
import particlelab.collision.SphereTests;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * The lecture's cheat for fast bullets: "if the bullet speed is high, consider it travel along
 * a straight line; adjust its position if necessary". A ray (hitscan) from the gun to the
 * target's centre always hits, with no travel time and no drop. A real projectile fired level
 * at the centre with speed v takes {@code t = d/v} to cover the distance d and falls
 * {@code ½·g·t²} meanwhile; the cheat is good enough while that drop stays within the target's
 * radius r, that is for {@code d < v·√(2r/g)}.
 *
 * <p>The stepped projectile (semi-implicit Euler, the shared integrator) falls more: with
 * {@code N = d/(v·h)} steps, {@code n = floor(N)}, {@code f = N − n}, its samples are
 * {@code y_i = −g·h²·i(i+1)/2} and the chord crossing {@code x = d} lies
 * {@code ½·g·h²·(n+1)(n+2f) = ½·g·t² + ½·g·h·t + ½·g·h²·f(1−f)} below the centre: the
 * lecture's offset of half a step, {@code ½·g·h·t}, plus at most {@code g·h²/8}.
 *
 * <p>"Adjust its position": a bullet moving {@code v·h} per step, more than the target's size,
 * would jump over the target or be found behind it. Each step is a straight segment, so the
 * swept tests of {@code particlelab.collision} find the first point of the segment that
 * touches the target, and the impact is placed there, not at the step's end.
 */
public final class Hitscan {

    /** Steps the projectile and sweeps each step's segment against the target. */
    private final Flight flight;
    private final Particle projectile = new Particle();
    private float stepSeconds;
    private final int maxSteps;
    private final Vector3f centre = new Vector3f();
    private final Vector3f normal = new Vector3f();
    /** The last disc's plane, rebuilt only when the distance changes. */
    private Plane face;
    private float faceDistance;
    /** The sphere's radius of the shot under way (m). */
    private float sphereRadius;
    /** The disc's plane, swept with radius 0. */
    private final Flight.Sweep faceSweep = (from, to) -> face.sweep(from, to, 0f, normal);
    /** The sphere, which does not move: its segment is a point. */
    private final Flight.Sweep sphereSweep = (from, to) -> SphereTests.sweep(from, to, centre,
            centre, sphereRadius);

    /**
     * Create a projectile range.
     *
     * @param integrator the scene's forces, gravity along −y (not null)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param maxSteps give up on a projectile that has not reached the target after this many
     *     steps (&ge;1)
     */
    public Hitscan(ParticleIntegrator integrator, float stepSeconds, int maxSteps) {
        this.flight = new Flight(Validate.notNull(integrator, "integrator"));
        this.stepSeconds = Validate.positive(stepSeconds, "step h (s)");
        if (maxSteps < 1) {
            throw new IllegalArgumentException("max steps must be >= 1, but was " + maxSteps);
        }
        this.maxSteps = maxSteps;
    }

    /**
     * Change the step the projectile flies with, in place (a range reused for another h).
     *
     * @param newStepSeconds h (in seconds, finite, &gt;0)
     */
    public void setStepSeconds(float newStepSeconds) {
        stepSeconds = Validate.positive(newStepSeconds, "step h (s)");
    }

    /**
     * The drop the straight line ignores: {@code ½·g·(d/v)²}.
     *
     * @param gravity g (in m/s², finite, &gt;0)
     * @param distance d (in metres, finite, &gt;0)
     * @param speed v (in m/s, finite, &gt;0)
     * @return the drop (in metres, &ge;0)
     */
    public static double formulaDrop(double gravity, double distance, double speed) {
        check(gravity, distance, speed);
        double time = distance / speed;
        return 0.5 * gravity * time * time;
    }

    /**
     * The drop of the stepped projectile at the crossing of {@code x = d}, read on the chord
     * between two samples: {@code ½·g·h²·(n+1)(n+2f)} with {@code N = d/(v·h)},
     * {@code n = floor(N)}, {@code f = N − n}.
     *
     * @param gravity g (in m/s², finite, &gt;0)
     * @param distance d (in metres, finite, &gt;0)
     * @param speed v (in m/s, finite, &gt;0)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @return the drop (in metres, &gt;0)
     */
    public static double steppedDrop(double gravity, double distance, double speed,
            double stepSeconds) {
        check(gravity, distance, speed);
        Validate.positive(stepSeconds, "step h (s)");
        double steps = distance / (speed * stepSeconds);
        double whole = Math.floor(steps);
        double fraction = steps - whole;
        return 0.5 * gravity * stepSeconds * stepSeconds * (whole + 1.0)
                * (whole + 2.0 * fraction);
    }

    /**
     * The distance below which the cheat is good enough: the drop {@code ½·g·(d/v)²} stays
     * within the radius, {@code d < v·√(2r/g)}.
     *
     * @param speed v (in m/s, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &gt;0)
     * @param gravity g (in m/s², finite, &gt;0)
     * @return the distance (in metres, &gt;0)
     */
    public static double cheatDistance(double speed, double radiusMetres, double gravity) {
        Validate.positive(gravity, "gravity g (m/s^2)");
        Validate.positive(radiusMetres, "target radius r (m)");
        Validate.positive(speed, "speed v (m/s)");
        return speed * Math.sqrt(2.0 * radiusMetres / gravity);
    }

    /**
     * Fire a projectile level from the origin along +x at a thin disc of radius r facing the
     * gun, centred at {@code (d, 0, 0)}: each step's segment is tested against the disc's
     * plane {@code x = d} (the swept plane test, radius 0), the impact placed where the segment
     * crosses it, and the disc is hit if that point is within r of the centre.
     *
     * @param speed v (in m/s, finite, &gt;0)
     * @param distance d (in metres, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &gt;0)
     * @param storeResult storage for the impact (not null, modified)
     * @return true if the projectile reached the plane within the steps allowed
     */
    public boolean fireAtDisc(float speed, float distance, float radiusMetres,
            TargetImpact storeResult) {
        Validate.notNull(storeResult, "storeResult");
        checkShot(speed, distance, radiusMetres);
        if (face == null || faceDistance != distance) {
            // The disc's plane n·x = c with n = −x facing the gun: n·x − c = d − x.
            face = new Plane(new Vector3f(-1f, 0f, 0f), -distance);
            faceDistance = distance;
        }
        launch(speed);
        for (int step = 1; step <= maxSteps; ++step) {
            double fraction = flight.step(projectile, stepSeconds, faceSweep);
            if (fraction != Flight.NO_LANDING) {
                store(fraction, step, storeResult);
                // Fired in the x-y plane: the distance from the centre is |y|.
                storeResult.set(true, Math.abs(storeResult.getY()) <= radiusMetres,
                        storeResult.getX(), storeResult.getY(), storeResult.getTimeSeconds(),
                        step);
                return true;
            }
        }
        storeResult.set(false, false, Double.NaN, Double.NaN, Double.NaN, maxSteps);
        return false;
    }

    /**
     * Fire a projectile level from the origin along +x at a sphere of radius r centred at
     * {@code (d, 0, 0)}: each step's segment is swept against the sphere and the impact placed
     * at the segment's first point on its surface, however far the step goes.
     *
     * @param speed v (in m/s, finite, &gt;0)
     * @param distance d (in metres, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &gt;0)
     * @param storeResult storage for the impact (not null, modified)
     * @return true if the projectile hit the sphere within the steps allowed
     */
    public boolean fireAtSphere(float speed, float distance, float radiusMetres,
            TargetImpact storeResult) {
        Validate.notNull(storeResult, "storeResult");
        checkShot(speed, distance, radiusMetres);
        centre.set(distance, 0f, 0f);
        sphereRadius = radiusMetres;
        launch(speed);
        double beyond = (double) distance + radiusMetres;
        for (int step = 1; step <= maxSteps; ++step) {
            double fraction = flight.step(projectile, stepSeconds, sphereSweep);
            if (fraction != Flight.NO_LANDING) {
                store(fraction, step, storeResult);
                return true;
            }
            if (projectile.position.x > beyond) {
                break;
            }
        }
        storeResult.set(false, false, Double.NaN, Double.NaN, Double.NaN, maxSteps);
        return false;
    }

    private void launch(float speed) {
        projectile.position.zero();
        projectile.velocity.set(speed, 0f, 0f);
    }

    /** Store the point at the fraction of the last step's segment as a hit. */
    private void store(double fraction, int step, TargetImpact storeResult) {
        double time = (step - 1 + fraction) * stepSeconds;
        storeResult.set(true, true, flight.crossingX(fraction), flight.crossingY(fraction),
                time, step);
    }

    private static void checkShot(float speed, float distance, float radiusMetres) {
        Validate.positive(speed, "speed v (m/s)");
        Validate.positive(distance, "distance d (m)");
        Validate.positive(radiusMetres, "target radius r (m)");
    }

    private static void check(double gravity, double distance, double speed) {
        Validate.positive(gravity, "gravity g (m/s^2)");
        Validate.positive(distance, "distance d (m)");
        Validate.positive(speed, "speed v (m/s)");
    }
}
