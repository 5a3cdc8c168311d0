package particlelab.demo;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Pause at the next contact, so a lecturer can talk about it: armed by its key, it hears the
 * epilogue of the demo's world ({@link ContactListener#resolved}) and pauses the clock from
 * inside the step that resolved the contact, which ends the frame right there
 * ({@link SimulationClock#setPaused}): {@code t} is the end of that step, and the views show
 * the bodies as the resolution left them. The HUD's time line then says which bodies met, how
 * fast they approached and when inside the step, until the next step is taken; while armed it
 * says so. A contact of bodies that were not approaching when the step began is a resting
 * contact (a ball lying on the ground meets it every step, closing at {@code g·h}, at the
 * step's start): the line says "resting", so it is not read as the moment the body stopped.
 *
 * <p>The key: when idle or while paused by Space, arm and run to the next contact; at a
 * contact, run on to the next one; while armed and running, cancel. Space resumes as ever
 * (and leaves the pause disarmed). One contact pauses once: the pause disarms as it stops.
 * Only the demo's own world is heard, not simulations beside it (Bounce's hidden lane).
 * Hearing and writing allocate nothing.
 */
final class ContactPause implements ContactListener {

    /** Room for the contact's description, so writing it never grows the builder. */
    private static final int DESCRIPTION_CAPACITY = 256;

    private final SimulationClock clock;
    private final List<DemoParticle> particles;
    /** The contact that paused the clock: bodies, time, approach speed. */
    private final StringBuilder description = new StringBuilder(DESCRIPTION_CAPACITY);
    private boolean armed;
    private boolean atContact;
    /** Contacts resolved in the step that paused, after the first. */
    private int moreContacts;
    /** The world's step count during the step that paused. */
    private long pausedStep;
    /** The world that resolved the contact (null before the first). */
    private World pausedWorld;
    private KeyBinding key;
    private KeyBinding pauseKey;
    /** Scratch: the bodies' velocities at the step's start (m/s). */
    private final Vector3f startVelocityA = new Vector3f();
    private final Vector3f startVelocityB = new Vector3f();

    /**
     * Create a disarmed pause for one demo.
     *
     * @param clock the demo's clock, paused at the contact (not null)
     * @param particles the demo's particles, whose labels name the bodies (not null, live)
     */
    ContactPause(SimulationClock clock, List<DemoParticle> particles) {
        this.clock = clock;
        this.particles = particles;
    }

    /**
     * Name the keys the HUD mentions.
     *
     * @param binding this pause's key (not null)
     * @param pause the demo's pause / resume key (not null)
     */
    void setKeys(KeyBinding binding, KeyBinding pause) {
        key = binding;
        pauseKey = pause;
    }

    /**
     * The key's action: arm and run to the next contact (resuming a paused clock), or, while
     * armed and running, cancel.
     */
    void press() {
        if (armed && !clock.isPaused()) {
            armed = false;
            return;
        }
        armed = true;
        atContact = false;
        clock.setPaused(false);
    }

    /**
     * Test whether the next resolved contact will pause the clock.
     *
     * @return true if armed
     */
    boolean isArmed() {
        return armed;
    }

    /**
     * Test whether the clock stands at the step of the contact that paused it: not after a
     * step back (Home, the timeline) to another recorded step, whose HUD must not describe
     * it.
     *
     * @return true if paused at a contact, that step shown
     */
    boolean isAtContact() {
        return atContact && clock.isPaused() && pausedWorld.getStepCount() == pausedStep + 1L;
    }

    /** A step begins: the clock has left the contact's step (resumed or single-stepped). */
    void beforeStep() {
        atContact = false;
    }

    /** The scene went back to its start: no contact is shown; armed stays armed. */
    void restart() {
        atContact = false;
    }

    /**
     * Append, for the time line of a clock paused at a contact, which contact and the keys,
     * e.g. {@code PAUSED at contact: ball - ground, approach 8.82 m/s at t = 0.8952 s (Enter:
     * next contact, Space resumes)}. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     */
    void appendAtContact(StringBuilder text) {
        text.append("PAUSED at contact: ").append(description);
        if (moreContacts > 0) {
            text.append(" (+").append(moreContacts).append(" more in this step)");
        }
        text.append(" (").append(key.getKeyLabel()).append(": next contact, ")
                .append(pauseKey.getKeyLabel()).append(" resumes)");
    }

    /**
     * Append, for the time line of an armed pause, that it waits for a contact, e.g.
     * {@code pausing at the next contact (Enter cancels)}. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     */
    void appendArmed(StringBuilder text) {
        text.append("pausing at the next contact (").append(key.getKeyLabel())
                .append(" cancels)");
    }

    @Override
    public void resolved(Contact contact, World world) {
        if (armed) {
            armed = false;
            atContact = true;
            moreContacts = 0;
            pausedStep = world.getStepCount();
            pausedWorld = world;
            describe(contact);
            clock.setPaused(true);
        } else if (atContact && world.getStepCount() == pausedStep) {
            ++moreContacts;
        }
    }

    /** Write which bodies met, when and how fast they approached, without allocating. */
    private void describe(Contact contact) {
        description.setLength(0);
        appendBody(contact.getBodyA());
        description.append(" - ");
        if (contact.getBodyB() != null) {
            appendBody(contact.getBodyB());
        } else if (contact.getRule() instanceof SurfaceRule) {
            description.append(((SurfaceRule) contact.getRule()).getName());
        } else {
            description.append("a surface");
        }
        description.append(isResting(contact) ? ", resting: approach " : ", approach ");
        TextFormat.appendFixed(description, contact.getApproachSpeed(), 2).append(" m/s");
        if (isResting(contact)) {
            description.append(" (this step's h·a alone)");
        }
        description.append(" at t = ");
        TextFormat.appendFixed(description, contact.getTimeSeconds(), 4).append(" s");
    }

    /**
     * Test whether the bodies were not approaching along the contact's normal when the step
     * began, so only the step's own forces brought them together: a resting contact.
     */
    private boolean isResting(Contact contact) {
        contact.getBodyA().copyPreviousVelocity(startVelocityA);
        if (contact.getBodyB() != null) {
            startVelocityA.subtractLocal(contact.getBodyB().copyPreviousVelocity(startVelocityB));
        }
        return startVelocityA.dot(contact.getNormal()) >= 0f;
    }

    /** A body by its particle's label, else by its number in the world. */
    private void appendBody(Body body) {
        for (int i = 0; i < particles.size(); ++i) {
            if (particles.get(i).getBody() == body) {
                description.append(particles.get(i).getLabel());
                return;
            }
        }
        description.append("body ").append(body.getId());
    }
}
