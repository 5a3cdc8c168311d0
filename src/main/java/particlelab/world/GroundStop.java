package particlelab.world;

import java.util.ArrayList;
import java.util.List;
import particlelab.physics.Particle;

/**
 * The lecture's stop at the ground, as a rule of a {@link World}: a body added here that comes
 * down through {@code y = 0} stops where its step's straight segment crossed the ground and is
 * held there, and its landing is kept: where ({@code x}), when (its flight time at the step's
 * start plus {@code fraction·h}), and the state the step had left it in below the ground
 * before the stop moved it (the last row of an exported trajectory, as {@code trajectory
 * --until-ground} prints it). One place holds a stopped body's landing; its launch state and
 * flight time are the {@link Body}'s.
 *
 * <p>The rule is {@code SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT)}, limited
 * to the bodies added ({@link SurfaceRule#limitTo}): the world finds the crossing with the
 * plane's swept test and puts the body at the crossing's point of the segment, so the landing
 * is a contact its listeners and log see like any other. The stop listens to the world (made
 * with its first body): in the prologue ({@link #accept}) it copies the state the step left
 * the body in, in the epilogue ({@link #resolved}) it records the landing and puts the body
 * on the ground exactly. Nothing is stepped twice. Allocates nothing once its bodies are
 * added.
 */
public final class GroundStop implements ContactListener, StepListener, StateRecord {

    /** The ints of one stopped body in a {@link StateSlab}: 2 flags, x, the time. */
    public static final int STATE_INTS_PER_BODY = 2 + 1 + 2;

    /** One stopped body and its landing. */
    private static final class Stop {
        final Body body;
        /** The state the step left the body in when the stop found it below the ground. */
        final Particle belowGround = new Particle();
        boolean landed;
        boolean landedThisStep;
        float landingX = Float.NaN;
        double landingSeconds = Double.NaN;

        Stop(Body body) {
            this.body = body;
        }
    }

    private final World world;
    private final List<Stop> stops = new ArrayList<>();
    /** The rule on the world, made with the first body (null before). */
    private SurfaceRule rule;
    /** h of the step under way (in seconds). */
    private float stepSeconds;

    /**
     * Create the ground stop of a world; it joins the world with its first body.
     *
     * @param world the world its bodies are in (not null)
     */
    public GroundStop(World world) {
        if (world == null) {
            throw new IllegalArgumentException("world must be a world, but was null");
        }
        this.world = world;
    }

    /**
     * Make a body stop at the ground (again: nothing changes). The first body puts the rule
     * and this listener on the world. Call while building a scene.
     *
     * @param body a body of the world (not null)
     * @return the body's place among the stopped bodies (&ge;0)
     */
    public int add(Body body) {
        if (body == null) {
            throw new IllegalArgumentException("body must be a body, but was null");
        }
        int index = indexOf(body);
        if (index >= 0) {
            return index;
        }
        if (rule == null) {
            rule = SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT);
            world.addRule(rule);
            world.addContactListener(this);
            world.addStepListener(this);
        }
        rule.limitTo(body);
        stops.add(new Stop(body));
        return stops.size() - 1;
    }

    /**
     * Find a body's place among the stopped bodies.
     *
     * @param body any body (may be null)
     * @return its place (&ge;0), or -1 if it does not stop at the ground
     */
    public int indexOf(Body body) {
        for (int i = 0; i < stops.size(); ++i) {
            if (stops.get(i).body == body) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Count the bodies that stop at the ground.
     *
     * @return the count (&ge;0)
     */
    public int countBodies() {
        return stops.size();
    }

    /**
     * Access the world's rule: the ground, the swept test, the stick response.
     *
     * @return the rule, or null before the first body was added
     */
    public SurfaceRule getRule() {
        return rule;
    }

    /**
     * Test whether a stopped body has come down through the ground since its launch.
     *
     * @param index its place ({@link #add})
     * @return true if it landed
     */
    public boolean hasLanded(int index) {
        return stops.get(index).landed;
    }

    /**
     * Test whether a stopped body landed in the step under way or just taken (from the
     * epilogue of the landing step until the next step starts).
     *
     * @param index its place ({@link #add})
     * @return true if it landed in that step
     */
    public boolean hasLandedThisStep(int index) {
        return stops.get(index).landedThisStep;
    }

    /**
     * Return where a stopped body crossed the ground: x of the crossing on the step's
     * straight segment, as the world's swept contact put it there.
     *
     * @param index its place ({@link #add})
     * @return x (in metres; NaN if it has not landed)
     */
    public float getLandingX(int index) {
        return stops.get(index).landingX;
    }

    /**
     * Return when a stopped body crossed the ground since its launch: its flight time at the
     * landing step's start plus {@code fraction·h}, the contact's fraction of the step.
     *
     * @param index its place ({@link #add})
     * @return the time (in seconds; NaN if it has not landed)
     */
    public double getLandingSeconds(int index) {
        return stops.get(index).landingSeconds;
    }

    /**
     * Access the state the landing step left a stopped body in below the ground, before the
     * stop moved it to the crossing: the semi-implicit Euler step's P and V, bit for bit (the
     * body's other contacts earlier in that step included).
     *
     * @param index its place ({@link #add})
     * @return the live state (do not modify; meaningful once it landed)
     */
    public Particle getStateBelowGround(int index) {
        return stops.get(index).belowGround;
    }

    /**
     * Forget a stopped body's landing: it is in flight again (its body is relaunched by
     * {@link Body#restart} or the world's restart).
     *
     * @param index its place ({@link #add})
     */
    public void restart(int index) {
        Stop stop = stops.get(index);
        stop.landed = false;
        stop.landingX = Float.NaN;
        stop.landingSeconds = Double.NaN;
    }

    /** Before a step: no body has landed in it yet; remember h for the landing times. */
    @Override
    public void beforeStep(World stepping, float newStepSeconds) {
        stepSeconds = newStepSeconds;
        for (int i = 0; i < stops.size(); ++i) {
            stops.get(i).landedThisStep = false;
        }
    }

    /**
     * The prologue of a contact with the ground: the body is still where the step left it,
     * below the ground; keep that state for the landing.
     */
    @Override
    public boolean accept(Contact contact, World stepping) {
        if (contact.getRule() == rule) {
            int index = indexOf(contact.getBodyA());
            if (index >= 0) {
                Particle from = contact.getBodyA().getParticle();
                Particle below = stops.get(index).belowGround;
                below.setMass(from.getMass());
                below.position.set(from.position);
                below.velocity.set(from.velocity);
            }
        }
        return true;
    }

    /**
     * The epilogue of a contact with the ground: the stick response left the body held at the
     * crossing; record the landing, and put it on the ground exactly (the segment's point is
     * {@code y = 0} to float round-off).
     */
    @Override
    public void resolved(Contact contact, World stepping) {
        if (contact.getRule() != rule) {
            return;
        }
        int index = indexOf(contact.getBodyA());
        if (index < 0) {
            return;
        }
        Stop stop = stops.get(index);
        Particle particle = stop.body.getParticle();
        stop.landed = true;
        stop.landedThisStep = true;
        stop.landingX = particle.position.x;
        // The body's flight time is the step's start during its contacts.
        stop.landingSeconds = stop.body.getFlightSeconds()
                + (double) contact.getFraction() * stepSeconds;
        particle.position.y = 0f;
    }

    @Override
    public int countStateInts() {
        return stops.size() * STATE_INTS_PER_BODY;
    }

    @Override
    public void writeState(StateSlab slab) {
        for (int i = 0; i < stops.size(); ++i) {
            Stop stop = stops.get(i);
            slab.putBoolean(stop.landedThisStep);
            slab.putBoolean(stop.landed);
            slab.putFloat(stop.landingX);
            slab.putDouble(stop.landingSeconds);
        }
    }

    @Override
    public void readState(StateSlab slab) {
        for (int i = 0; i < stops.size(); ++i) {
            Stop stop = stops.get(i);
            stop.landedThisStep = slab.getBoolean();
            stop.landed = slab.getBoolean();
            stop.landingX = slab.getFloat();
            stop.landingSeconds = slab.getDouble();
        }
    }
}
