package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.physics.EnergyLedger;
import particlelab.physics.Particle;
import particlelab.rigid.RigidBody;

/**
 * The {@link EnergyLedger} of a {@link World}, kept by listening to its steps: where the
 * energy of the world's bodies goes (issue 32).
 *
 * <ul>
 * <li>each step, every body the integrator moved is booked the work its forces did as the
 * step applied them ({@link EnergyLedger#addStepWork}), with its start state
 * ({@link Body#copyPreviousPosition}, {@link Body#copyPreviousVelocity}) and the velocity the
 * step moved it with (the previous one plus {@link Body#copyGainedVelocity the gain});</li>
 * <li>each resolved contact books its {@link Contact#getImpactLossJoules() impact loss} and
 * {@link Contact#getScriptWorkJoules() script work};</li>
 * <li>a kinematic body is the script's: whatever its energy does (a clip's keyframes, a
 * paddle's velocity set before the step) is script work;</li>
 * <li>energy put into the other bodies between steps (a launch, a drag with the mouse, a
 * changed parameter), and a body added or destroyed, move the start;</li>
 * <li>the rest is the numerical column: what the steps themselves created or destroyed,
 * penetration corrections and the geometry of a swept contact included.</li>
 * </ul>
 * A body's energy counts its rotation {@code ½ωᵀIω} if it has a rotation part. Allocates
 * nothing per step once the list of bodies added in a step has met its largest size.
 *
 * <p>A step costs O(bodies): each body's start is found by a search that resumes where the
 * last one ended, since the world keeps its bodies in order (removing one keeps the order
 * of the rest, adding one puts it at the end); a body added in the step costs a look
 * through those added in it.
 */
public final class WorldEnergy implements StepListener, ContactListener, BodyListener {

    /** Room for this many bodies at the start of a step before the arrays grow. */
    private static final int INITIAL_CAPACITY = 256;

    private final World world;
    private final boolean listensToSteps;
    private final EnergyLedger ledger = new EnergyLedger();
    /** Measures one body at a time. */
    private final EnergyLedger probe = new EnergyLedger();
    /** The bodies at the start of the step under way, in the world's order ... */
    private Body[] startBodies = new Body[INITIAL_CAPACITY];
    /** ... and the energy each had then, with the forces of then (J). */
    private double[] startEnergies = new double[INITIAL_CAPACITY];
    private int startCount;
    /** Where the next search of the start's bodies begins ({@link #indexAtStart}). */
    private int searchFrom;
    /** Bodies looked at by the searches since this was made: the cost, for tests. */
    private long searchSteps;
    /** Bodies added during the step under way: not moved by it, their energy enters. */
    private final List<Body> addedInStep = new ArrayList<>(INITIAL_CAPACITY);
    private boolean stepping;
    /** h of the step under way (s). */
    private float stepSeconds;
    /** The energy of the bodies that are not kinematic after the last step (J). */
    private double lastDynamicJoules;
    /** The energy of the kinematic bodies after the last step (J). */
    private double lastKinematicJoules;
    /** The columns the world's forces and rules give ({@link EnergyLedger#KINETIC} ...). */
    private int columns;
    /** Scratch: a body at the start of the step. */
    private final Particle atStart = new Particle();
    /** Scratch: a previous position (m). */
    private final Vector3f previousPosition = new Vector3f();
    /** Scratch: the velocity the step moved a body with (m/s). */
    private final Vector3f stepVelocity = new Vector3f();
    /** Scratch: a rigid body's ω in its own frame (rad/s). */
    private final Vector3f bodyOmega = new Vector3f();

    /**
     * Keep the ledger of a world: listen to its steps, contacts and bodies, and start from
     * its state now.
     *
     * @param world the world (not null)
     */
    public WorldEnergy(World world) {
        this(world, true);
    }

    /**
     * Keep the ledger of a world, listening to its contacts and bodies, and to its steps if
     * asked: otherwise the owner calls {@link #beforeStep} and {@link #afterStep} itself, at
     * the same moments (a demo's part, which the demo's own step listener calls, so a ledger
     * made inside a step starts with that step).
     *
     * @param world the world (not null)
     * @param listenToSteps true to add this as a step listener of the world
     */
    public WorldEnergy(World world, boolean listenToSteps) {
        if (world == null) {
            throw new IllegalArgumentException("world must be a world, but was null");
        }
        this.world = world;
        this.listensToSteps = listenToSteps;
        if (listenToSteps) {
            world.addStepListener(this);
        }
        world.addContactListener(this);
        world.addBodyListener(this);
        restart();
    }

    /** Stop listening to the world. */
    public void detach() {
        if (listensToSteps) {
            world.removeStepListener(this);
        }
        world.removeContactListener(this);
        world.removeBodyListener(this);
    }

    /**
     * Start again from the world's state now: the start is its energy, every flow zero, and
     * the columns are those its bodies' forces and its rules give now.
     */
    public void restart() {
        columns = EnergyLedger.KINETIC;
        for (int i = 0; i < world.countBodies(); ++i) {
            Body body = world.getBody(i);
            columns |= EnergyLedger.columnsOf(body.getIntegrator());
            if (body.isKinematic()) {
                columns |= EnergyLedger.SCRIPT;
            }
        }
        for (int i = 0; i < world.countRules(); ++i) {
            columns |= EnergyLedger.IMPACT;
            // an impulse and a stop take energy; a clip, or a response the ledger does not
            // know (a demo's own, choosing per contact), may also give some: a script's
            ContactResponse response = world.getRule(i).getResponse();
            boolean known = response instanceof ImpulseResponse
                    || response instanceof ScriptedResponse
                    && !((ScriptedResponse) response).isClip();
            if (!known) {
                columns |= EnergyLedger.SCRIPT;
            }
        }
        measure();
        ledger.start();
        addedInStep.clear();
    }

    /**
     * Access the ledger.
     *
     * @return the live ledger (not null; read it, don't book into it)
     */
    public EnergyLedger getLedger() {
        return ledger;
    }

    /**
     * Tell which columns this world has: {@link EnergyLedger#KINETIC} always, the others
     * where its forces or rules give them (as of the last {@link #restart}).
     *
     * @return the columns, OR-ed
     */
    public int getColumns() {
        return columns;
    }

    @Override
    public void beforeStep(World stepping, float stepSeconds) {
        // What changed since the last step: the scripts' doing for kinematic bodies, energy
        // put in by hand for the rest.
        double dynamic = 0.0;
        double kinematic = 0.0;
        startCount = world.countBodies();
        if (startBodies.length < startCount) {
            startBodies = new Body[2 * startCount];
            startEnergies = new double[2 * startCount];
        }
        for (int i = 0; i < startCount; ++i) {
            Body body = world.getBody(i);
            double joules = energyNow(body);
            startBodies[i] = body;
            startEnergies[i] = joules - rotationJoules(body);
            if (body.isKinematic()) {
                kinematic += joules;
            } else {
                dynamic += joules;
            }
        }
        ledger.addToStart(dynamic - lastDynamicJoules);
        ledger.addScriptWork(kinematic - lastKinematicJoules);
        lastDynamicJoules = dynamic;
        lastKinematicJoules = kinematic;
        addedInStep.clear();
        searchFrom = 0;
        this.stepSeconds = stepSeconds;
        this.stepping = true;
    }

    @Override
    public void resolved(Contact contact, World stepping) {
        ledger.addImpactLoss(contact.getImpactLossJoules());
        ledger.addScriptWork(contact.getScriptWorkJoules());
    }

    @Override
    public void bodyAdded(World stepping, Body body) {
        if (this.stepping) {
            addedInStep.add(body);
            ledger.addToStart(energyNow(body));
        }
    }

    @Override
    public void bodyRemoved(World stepping, Body body) {
        double joules = energyNow(body);
        if (this.stepping) {
            // Leaves after the step's epilogue: book its step, then its energy leaves.
            bookStep(body, stepSeconds);
            ledger.addToStart(-joules);
        } else if (body.isKinematic()) {
            lastKinematicJoules -= joules;
        } else {
            lastDynamicJoules -= joules;
            ledger.addToStart(-joules);
        }
    }

    @Override
    public void afterStep(World stepping, float stepSeconds) {
        this.stepping = false;
        searchFrom = 0;
        for (int i = 0; i < world.countBodies(); ++i) {
            bookStep(world.getBody(i), stepSeconds);
        }
        addedInStep.clear();
        for (int i = 0; i < startCount; ++i) {
            startBodies[i] = null;
        }
        measure();
    }

    /**
     * Book one body's step: its forces' work, or a kinematic body's change as script; and if
     * its forces changed during the step (a demo switching gravity on at an impact), the
     * energy that change alone made: it was put in, not created by the step.
     */
    private void bookStep(Body body, float stepSeconds) {
        if (!addedInStep.isEmpty() && addedInStep.contains(body)) {
            return;
        }
        double before = energyAt(body, body.previousPosition, body.previousVelocity);
        int at = indexAtStart(body);
        if (at >= 0) {
            // the same state as at the start, measured with the forces now (the rotation
            // left out: the step turned it, and that is the step's)
            ledger.addToStart(before - rotationJoules(body) - startEnergies[at]);
        }
        if (body.isKinematic()) {
            double after = energyAt(body, body.particle.position, body.particle.velocity);
            ledger.addScriptWork(after - before);
            return;
        }
        if (body.isHeld() && body.previousPosition.equals(body.particle.position)) {
            return;
        }
        atStart.setMass(body.getMass());
        atStart.setState(body.copyPreviousPosition(previousPosition), body.previousVelocity);
        stepVelocity.set(body.previousVelocity).addLocal(body.gainedVelocity);
        ledger.addStepWork(body.getIntegrator(), atStart, stepSeconds, stepVelocity);
    }

    /**
     * Count the bodies the searches for a body's start have looked at, since this was made:
     * about one per body and step when the world keeps its order.
     *
     * @return the count (&ge;0)
     */
    long countSearchSteps() {
        return searchSteps;
    }

    /**
     * Find a body among those at the start of the step (-1: added since): from where the
     * last search ended, then from the beginning, so bodies asked for in the world's order
     * cost one look each.
     */
    private int indexAtStart(Body body) {
        for (int i = searchFrom; i < startCount; ++i) {
            ++searchSteps;
            if (startBodies[i] == body) {
                searchFrom = i + 1;
                return i;
            }
        }
        for (int i = 0; i < Math.min(searchFrom, startCount); ++i) {
            ++searchSteps;
            if (startBodies[i] == body) {
                searchFrom = i + 1;
                return i;
            }
        }
        return -1;
    }

    /** Measure every body into the ledger, and remember the dynamic and kinematic sums. */
    private void measure() {
        ledger.beginState();
        double dynamic = 0.0;
        double kinematic = 0.0;
        for (int i = 0; i < world.countBodies(); ++i) {
            Body body = world.getBody(i);
            ledger.addBody(body.getIntegrator(), body.particle);
            ledger.addKinetic(rotationJoules(body));
            double joules = energyNow(body);
            if (body.isKinematic()) {
                kinematic += joules;
            } else {
                dynamic += joules;
            }
        }
        ledger.endState();
        lastDynamicJoules = dynamic;
        lastKinematicJoules = kinematic;
    }

    private double energyNow(Body body) {
        return energyAt(body, body.particle.position, body.particle.velocity);
    }

    /** One body's energy with the given position and velocity (J). */
    private double energyAt(Body body, Vector3f position, Vector3f velocity) {
        atStart.setMass(body.getMass());
        atStart.setState(position, velocity);
        probe.beginState();
        probe.addBody(body.getIntegrator(), atStart);
        probe.addKinetic(rotationJoules(body));
        probe.endState();
        return probe.total();
    }

    private double rotationJoules(Body body) {
        RigidBody rigid = body.getRigidBody();
        return rigid == null ? 0.0 : rigid.rotationalEnergy(bodyOmega);
    }
}
