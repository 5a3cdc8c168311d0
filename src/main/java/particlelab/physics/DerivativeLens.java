package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The derivative lens (issue 32 §2): one step looked at closely, to tell apart what slides 8,
 * 12 and 14 define and what the step uses. At step i of step length h:
 * <ul>
 * <li>the <b>chord</b> {@code (P_{i+1} − P_i)/h}, the slope of the straight line the step
 * draws;</li>
 * <li>the <b>step's velocity</b>, the one the step moved the particle with: {@code V_{i+1}}
 * for the lecture's semi-implicit Euler step ({@code P ← P + h·V} after {@code V ← V + h·a}),
 * so there the chord <em>is</em> {@code V_{i+1}};</li>
 * <li>the <b>exact tangents</b> {@code dP/dt} of the true motion at {@code t_i} and at the
 * step's middle {@code t_i + h/2}, which the caller gives (a closed form, an exact path).
 * </li>
 * </ul>
 * Under gravity alone the velocity update is exact, so the exact tangent at {@code t_i} is
 * {@code V_i} and at the middle {@code V_i + g·h/2}: the chord differs from them by
 * {@code g·h} and {@code g·h/2}, first order in h ({@code DerivativeLensTest}).
 *
 * <p>Allocates nothing: the results are fields rewritten by each {@link #look}.
 */
public final class DerivativeLens {

    /** {@code P_i}, the step's start (m). */
    public final Vector3f startPosition = new Vector3f();
    /** {@code V_i}, the velocity at the step's start (m/s). */
    public final Vector3f startVelocity = new Vector3f();
    /** {@code P_{i+1}}, where the step ends (m). */
    public final Vector3f endPosition = new Vector3f();
    /** The step's velocity, {@code V_{i+1}} for the lecture's step (m/s). */
    public final Vector3f stepVelocity = new Vector3f();
    /** The chord {@code (P_{i+1} − P_i)/h} (m/s). */
    public final Vector3f chord = new Vector3f();
    /** The exact tangent {@code dP/dt} at {@code t_i} (m/s), as given. */
    public final Vector3f exactAtStart = new Vector3f();
    /** The exact tangent {@code dP/dt} at {@code t_i + h/2} (m/s), as given. */
    public final Vector3f exactAtMiddle = new Vector3f();
    private final Particle particle = new Particle();
    private float stepSeconds = Float.NaN;

    /**
     * Take one step of an integrator from a state and look at it: the chord and the step's
     * velocity. The exact tangents come with {@link #setExactTangents}.
     *
     * @param integrator the step (not null; the lecture's recipe for a
     *     {@link ParticleIntegrator})
     * @param massKg the particle's mass (in kg, &gt;0)
     * @param position {@code P_i} (in m, not null, not modified)
     * @param velocity {@code V_i} (in m/s, not null, not modified)
     * @param h the step's length (in seconds, finite, &gt;0)
     */
    public void look(ParticleIntegrator integrator, float massKg, Vector3f position,
            Vector3f velocity, float h) {
        if (!(h > 0f) || Float.isInfinite(h)) {
            throw new IllegalArgumentException("h must be finite and > 0, but was " + h);
        }
        stepSeconds = h;
        startPosition.set(position);
        startVelocity.set(velocity);
        particle.setMass(massKg);
        particle.setState(position, velocity);
        integrator.step(particle, h);
        endPosition.set(particle.position);
        stepVelocity.set(particle.velocity);
        // in float, as a student's code on the slide would: P_{i+1} − P_i, then / h
        endPosition.subtract(startPosition, chord).divideLocal(h);
    }

    /**
     * Give the exact motion's tangents for the step looked at.
     *
     * @param atStart {@code dP/dt} at {@code t_i} (in m/s, not null, not modified)
     * @param atMiddle {@code dP/dt} at {@code t_i + h/2} (in m/s, not null, not modified)
     */
    public void setExactTangents(Vector3f atStart, Vector3f atMiddle) {
        exactAtStart.set(atStart);
        exactAtMiddle.set(atMiddle);
    }

    /** @return h of the step looked at (in seconds; NaN before the first look) */
    public float getStepSeconds() {
        return stepSeconds;
    }

    /**
     * Copy the chord less the exact tangent at {@code t_i}: {@code g·h} under gravity alone.
     *
     * @param storeResult storage for the result (in m/s, modified)
     * @return storeResult
     */
    public Vector3f copyChordLessStartTangent(Vector3f storeResult) {
        return chord.subtract(exactAtStart, storeResult);
    }

    /**
     * Copy the chord less the exact tangent at the step's middle: {@code g·h/2} under
     * gravity alone.
     *
     * @param storeResult storage for the result (in m/s, modified)
     * @return storeResult
     */
    public Vector3f copyChordLessMiddleTangent(Vector3f storeResult) {
        return chord.subtract(exactAtMiddle, storeResult);
    }
}
