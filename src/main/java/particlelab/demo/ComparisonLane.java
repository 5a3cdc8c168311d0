package particlelab.demo;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import java.util.List;
import java.util.function.Supplier;
import particlelab.reference.CostMeter;
import particlelab.reference.ExactPath;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Scheme;
import particlelab.reference.SlideCode;
import particlelab.reference.Stepper;
import particlelab.coursework.RecipeExercise;
import particlelab.coursework.StudentRunner;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenError;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * A free-flight demo's comparison lane ({@code --set lane=...}, key L): one more sphere
 * launched with the same launch as one of the demo's spheres (the "followed" one), moved not
 * by the shared integrator but by
 * <ul>
 * <li>{@code slide}: the slide's own listing ({@link SlideCode}: allocating jME calls, the
 * step handed in as {@code tpf}), shown on the HUD line for line; or</li>
 * <li>one of the speed report's steppers ({@link Scheme}): forward Euler, the lecture's
 * semi-implicit Euler (the shared integrator itself), velocity Verlet, midpoint, RK4, in
 * double precision, at the demo's h; or</li>
 * <li>{@code student}: exercise 1's class, the student's own recipe ({@link RecipeExercise},
 * found by name: {@code particlelab.exercises.Recipe} under {@code gradle run},
 * {@code particlelab.solutions.Recipe} under {@code gradle run -Psolutions}), in float as it
 * takes it, each call on a worker thread ({@link StudentRunner}). A recipe that throws, gives
 * NaN or has not returned within a second stops the lane with one line on the HUD (the
 * exception, its message and the line of the student's file; the step and the value; "not
 * written yet" for the stub), and the demo runs on.</li>
 * </ul>
 * {@code off} (the default) hides the lane and leaves its HUD lines out: the picture and the
 * HUD are the demo's own.
 *
 * <p>The lane's sphere is a demo particle in the world, so it is drawn, trailed, replayed and
 * stopped at the ground like the others; its integrator has no forces, and before each world
 * step the lane puts it at its own state with the velocity of the chord to its next one, so
 * the world's step {@code P ← P + h·V} carries it there (to float round-off) and the ground's
 * swept test sees the lane's own segment. Its exact ghost follows the followed sphere's
 * forces. The lane's own state (double precision), the exact path it is measured against and
 * its readouts go into the replay ring.
 *
 * <p>The HUD's two lines: the lane's state and its cost per step, measured once per method by
 * the report's in-process meter ({@link CostMeter}, on a background thread, so no frame
 * waits for it); and the error as the viewer sees it, for the lane and for the followed
 * sphere, {@code |P − P_exact|} in metres, in pixels on the screen and in sphere radii,
 * "visible" from {@value ScreenError#VISIBLE_PIXELS} px or {@value ScreenError#VISIBLE_RADII}
 * radius ({@link ScreenError}); each measured at its sphere's landing, where its sphere stops:
 * the contact point against the exact path at the same time. The slide lane
 * adds its listing. Per step and per frame this allocates nothing, except the slide code
 * itself, whose allocation is its point (the HUD gives its bytes per step, measured).
 */
public final class ComparisonLane implements DemoPart {

    /** What moves the lane. */
    public enum Kind {
        /** No lane: hidden, out of the HUD (it flies the shared step, unseen). */
        OFF("off", "comparison lane off", Scheme.SEMI_IMPLICIT_EULER),
        /** The slide's own listing. */
        SLIDE("slide", "slide code", null),
        /** Forward Euler (the report's). */
        EULER("euler", "forward Euler", Scheme.FORWARD_EULER),
        /** The lecture's semi-implicit Euler: the shared integrator, through the report. */
        SEMI("semi", "semi-implicit Euler", Scheme.SEMI_IMPLICIT_EULER),
        /** Velocity Verlet as games write it (the report's). */
        VERLET("verlet", "velocity Verlet", Scheme.VELOCITY_VERLET),
        /** The explicit midpoint method (the report's). */
        MIDPOINT("midpoint", "midpoint (RK2)", Scheme.MIDPOINT),
        /** Classic fourth-order Runge-Kutta (the report's). */
        RK4("rk4", "RK4", Scheme.RUNGE_KUTTA_4),
        /** Exercise 1: the student's recipe ({@link RecipeExercise}), found by name. */
        STUDENT("student", "student's recipe", null);

        private final String id;
        private final String label;
        private final Scheme scheme;

        Kind(String id, String label, Scheme scheme) {
            this.id = id;
            this.label = label;
            this.scheme = scheme;
        }

        /** @return the {@code --set lane=} name */
        public String id() {
            return id;
        }

        /** @return the sphere's label */
        public String label() {
            return label;
        }

        /** @return the report's scheme that moves the lane (null for the slide and student) */
        public Scheme scheme() {
            return scheme;
        }
    }

    /** The parameter's command-line name. */
    public static final String PARAMETER = "lane";
    /** The lane sphere's colour: a green none of the free-flight demos uses. */
    private static final ColorRGBA COLOR = new ColorRGBA(0.45f, 1f, 0.35f, 1f);
    /** Steps per call of the cost meter's workload: some microseconds. */
    private static final int COST_STEPS = 64;
    /** The record's size: flags, the state, the slide's, the path's time, the readouts. */
    private static final int STATE_INTS = 2 + 12 + 6 + ExactPath.STATE_INTS + 10 + 2;
    private static final Kind[] KINDS = Kind.values();
    /** The student lane's line when the followed sphere has a force exercise 1 has not. */
    private static final String UNSUPPORTED_FOR_STUDENT = "these forces are not exercise 1's"
            + " (gravity, linear drag, thrust)";
    /** The lane at the start: off, so the picture and the HUD are the demo's own. */
    private static final Kind DEFAULT_KIND = Kind.OFF;

    private final Supplier<SlideCode> slideFactory;
    private final SlideCode slide;
    private final float radiusMetres;
    private DemoState demo;
    private DemoParticle followed;
    private DemoParticle particle;
    private ExactPath exact;
    private Kind kind = Kind.OFF;
    /** What the HUD says when the lane follows other forces than the sphere's (or null). */
    private String forcesNote;
    /** The lane's state (m, m/s), in double for the report's steppers. */
    private final MotionState state = new MotionState();
    /** The report's stepper for the forces now (null: to be built). */
    private Stepper stepper;
    private Scheme stepperScheme;
    private ForceModel model;
    /** The forces the model was built for: g, m, b, c, k. */
    private final float[] modelCoefficients = new float[7];
    private final float[] coefficients = new float[7];
    private final Vector3f gravityNow = new Vector3f();
    private final Vector3f scratchPosition = new Vector3f();
    private final Vector3f scratchVelocity = new Vector3f();
    /** Scratch: what a force the report does not model adds now (N + m/s², mixed). */
    private final Vector3f scratchForce = new Vector3f();
    /** The next step starts the lane from its sphere's launch state. */
    private boolean needsStart = true;
    /** The lane's step went non-finite (beyond its stability limit): it stopped. */
    private boolean blewUp;
    /** The followed sphere's forces are ones the report's steppers do not model. */
    private boolean unsupported;
    /** The readouts, noted after each step while the lane and the path fly. */
    private boolean hasErrors;
    private double laneDx;
    private double laneDy;
    private double followedDx;
    private double followedDy;
    private double slideDifference;
    /** Whether the lane's and the followed sphere's were flying when the step began. */
    private boolean laneWasFlying;
    private boolean followedWasFlying;
    /** Scratch: the exact path where a sphere landed inside the step (m). */
    private final double[] exactAtLanding = new double[3];
    /** Measured costs per kind (ns and bytes per step; NaN until measured). */
    private final double[] costNanos = new double[KINDS.length];
    private final double[] costBytes = new double[KINDS.length];
    private final boolean[] costAsked = new boolean[KINDS.length];
    /** The student's class could not be measured (it threw on the meter's thread). */
    private volatile boolean studentCostFailed;
    /** The student lane's class (null: exercise 1's, in the package the app was started in). */
    private String studentClass;
    /** How long one call of the student's recipe may take (ns). */
    private long studentLimitNanos = StudentRunner.DEFAULT_LIMIT_NANOS;
    /** The student lane's mover (null until the lane is first chosen). */
    private StudentRecipe student;
    /** g for the student's recipe (m/s²). */
    private final Vector3f studentGravity = new Vector3f();

    /**
     * Create a lane.
     *
     * @param slideFactory makes the demo's slide listing, reading the demo's live forces (not
     *     null; called twice: once for the lane, once for the cost meter's thread)
     * @param radiusMetres the spheres' drawn radius (in metres, &gt;0), for the error in radii
     */
    public ComparisonLane(Supplier<SlideCode> slideFactory, float radiusMetres) {
        this.slideFactory = slideFactory;
        this.slide = slideFactory.get();
        this.radiusMetres = radiusMetres;
        java.util.Arrays.fill(costNanos, Double.NaN);
        java.util.Arrays.fill(costBytes, Double.NaN);
    }

    /**
     * Add the lane's sphere to the demo, beside one of its spheres. Call from the demo's
     * {@code createScene()}, after the followed sphere was added, the lane having been added
     * to the demo with {@link DemoState#addPart}.
     *
     * @param launch the demo's launch control, which then moves the lane's launch too (not
     *     null)
     * @param followedSphere the sphere whose launch and forces the lane shares (not null)
     * @return the lane's sphere
     */
    public DemoParticle follow(LaunchControl launch, DemoParticle followedSphere) {
        if (demo == null) {
            throw new IllegalStateException("add the comparison lane to its demo with addPart"
                    + " before it follows a sphere");
        }
        followed = followedSphere;
        Particle source = followed.getParticle();
        particle = launch.add(demo.addParticle(kind.label(), COLOR,
                followed.copyLaunchPosition(scratchPosition),
                followed.copyLaunchVelocity(scratchVelocity), source.getMass(),
                new ParticleIntegrator()));
        // Out of the HUD's particle lines (the lane writes its own) and of the framing.
        particle.setParked(true);
        particle.setPathIntegrator(followed.getIntegrator());
        if (followed.stopsAtGround()) {
            particle.stopAtGround();
        }
        exact = new ExactPath(followed.getIntegrator());
        demo.addStateRecord(record());
        return particle;
    }

    /**
     * Return the lane now.
     *
     * @return the kind (not null)
     */
    public Kind getKind() {
        return kind;
    }

    /**
     * Access the lane's sphere.
     *
     * @return the demo particle (null before {@link #follow})
     */
    public DemoParticle getParticle() {
        return particle;
    }

    /**
     * Access the lane's own state, in double precision: what the stepper or the slide code
     * moved.
     *
     * @return the live state (do not modify)
     */
    public MotionState getState() {
        return state;
    }

    /**
     * Access the slide code's particle (moved only while the lane is {@code slide}).
     *
     * @return the live listing (do not modify)
     */
    public SlideCode getSlideCode() {
        return slide;
    }

    /**
     * Return the lane's error {@code |P − P_exact|} noted last: after the last step, or, once
     * the lane has landed, at its landing: its contact point against the exact path at that
     * moment (or where the exact path stopped, if it landed first).
     *
     * @return the distance (in metres; NaN before the first step)
     */
    public double getErrorMetres() {
        return hasErrors ? Math.hypot(laneDx, laneDy) : Double.NaN;
    }

    /**
     * Return the followed sphere's error {@code |P − P_exact|} at the same time, or, once it
     * has landed, at its landing (as for the lane).
     *
     * @return the distance (in metres; NaN before the first step)
     */
    public double getFollowedErrorMetres() {
        return hasErrors ? Math.hypot(followedDx, followedDy) : Double.NaN;
    }

    /**
     * Choose the class the student lane runs, and how long one of its calls may take: by
     * default {@code Recipe} in the package the app was started with ({@link
     * StudentRunner#className}) and {@link StudentRunner#DEFAULT_LIMIT_NANOS}. Applies from
     * the next launch; a class whose call was abandoned is left behind with its thread.
     *
     * @param className a {@link RecipeExercise}'s binary name (not null)
     * @param limitNanos how long one call may take before the lane gives up on it (in ns,
     *     &gt;0)
     */
    public void useStudentClass(String className, long limitNanos) {
        if (className == null || className.isEmpty()) {
            throw new IllegalArgumentException("the student lane's class must be named, but"
                    + " was " + (className == null ? "null" : "\"\""));
        }
        if (limitNanos <= 0L) {
            throw new IllegalArgumentException("the student lane's time limit (ns) must be"
                    + " > 0, but was " + limitNanos);
        }
        studentClass = className;
        studentLimitNanos = limitNanos;
        student = null;
        costAsked[Kind.STUDENT.ordinal()] = false;
        costNanos[Kind.STUDENT.ordinal()] = Double.NaN;
        studentCostFailed = false;
        needsStart = true;
    }

    /**
     * Return what stopped the student lane, in one line.
     *
     * @return the line ("not written yet", "step N: threw ...", ...), or null while the
     *     student's recipe runs (or the lane is another)
     */
    public String getStudentProblem() {
        if (kind != Kind.STUDENT || !blewUp || student == null) {
            return null;
        }
        return unsupported ? UNSUPPORTED_FOR_STUDENT : student.getProblem();
    }

    /**
     * Keep the demo the lane was added to ({@link DemoState#addPart}).
     *
     * @param owner the demo (not null)
     */
    @Override
    public void attach(DemoState owner) {
        demo = owner;
    }

    /**
     * Declare the lane's parameter,
     * {@code --set lane=off|slide|euler|semi|verlet|midpoint|rk4|student}, applied at the next
     * launch, off at the start.
     *
     * @param parameters the demo's parameters (not null, modified)
     */
    @Override
    public void declareParameters(DemoParameters parameters) {
        String[] names = new String[KINDS.length];
        for (int i = 0; i < KINDS.length; ++i) {
            names[i] = KINDS[i].id();
        }
        parameters.add(DemoParameter.choice(PARAMETER, "comparison lane", names,
                DEFAULT_KIND.ordinal(), DemoParameter.Applies.NEXT_LAUNCH,
                value -> select(KINDS[Math.round(value)])));
    }

    /** Bind L: the next lane, from a new launch. */
    @Override
    public void declareKeys() {
        demo.bindKey(KeyInput.KEY_L, "L",
                "comparison lane: off, slide code, the report's steppers, your recipe",
                this::cycle);
    }

    /**
     * Move the lane by one step of h, before the world's step: put the lane's sphere at the
     * lane's state with the chord's velocity, for the world's step to carry it to the next
     * state. Allocates nothing (but the slide code's own).
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    @Override
    public void beforeStep(float stepSeconds) {
        laneWasFlying = false;
        followedWasFlying = false;
        if (particle == null || blewUp) {
            return;
        }
        if (particle.hasLanded()) {
            // the exact path goes on while the followed sphere flies, for its error
            followedWasFlying = !needsStart && !followed.hasLanded();
            if (followedWasFlying) {
                exact.advance(stepSeconds);
            }
            return;
        }
        if (needsStart) {
            start();
        }
        laneWasFlying = true;
        followedWasFlying = !followed.hasLanded();
        refreshForces();
        Particle body = particle.getParticle();
        double[] p = state.position;
        body.position.set((float) p[0], (float) p[1], (float) p[2]);
        if (!advanceState(stepSeconds)) {
            blewUp = true;
            body.velocity.set(Vector3f.ZERO);
            particle.setHeld(true);
            return;
        }
        exact.advance(stepSeconds);
        body.velocity.set((float) ((p[0] - body.position.x) / stepSeconds),
                (float) ((p[1] - body.position.y) / stepSeconds),
                (float) ((p[2] - body.position.z) / stepSeconds));
    }

    /**
     * Note the readouts once the world has stepped: the lane, its exact path and the followed
     * sphere are then at the same time, the one the HUD's particle lines show. Reads only;
     * allocates nothing.
     *
     * @param stepSeconds h of the step just taken (in seconds, &gt;0)
     */
    @Override
    public void afterStep(float stepSeconds) {
        if (particle == null || blewUp || needsStart) {
            return;
        }
        noteErrors();
    }

    /** Start the lane again from its launch, at the demo's reset. */
    @Override
    public void onRestart() {
        needsStart = true;
        blewUp = false;
        hasErrors = false;
    }

    /**
     * Show the lane's sphere, or hide it while the lane is off, once a frame. Allocates
     * nothing.
     */
    @Override
    public void afterFrame() {
        if (particle == null) {
            return;
        }
        ParticleView view = demo.getWindow().getView(particle);
        if (view != null) {
            view.getNode().setCullHint(kind == Kind.OFF ? Spatial.CullHint.Always
                    : Spatial.CullHint.Inherit);
        }
        // off, its ghost would be drawn over the followed sphere's, doubling it
        demo.getExactGhosts().setGhostShown(demo.getParticles().indexOf(particle),
                kind != Kind.OFF);
    }

    /**
     * Append the lane's HUD lines (none while off): its state and measured cost, the error as
     * seen for it and the followed sphere, and the slide's listing for the slide lane.
     * Allocates nothing (the first call for a method starts its cost measurement).
     *
     * @param text where to append (not null, modified)
     */
    @Override
    public void writeHudLines(StringBuilder text) {
        if (particle == null || kind == Kind.OFF) {
            return;
        }
        measureCostOnce();
        text.append("Lane ").append(kind.label()).append(" (L):  ");
        String problem = getStudentProblem();
        if (problem != null) {
            // one line, what stopped the student's recipe, and no error to see; the demo
            // runs on
            text.append(problem);
            if (StudentRunner.NOT_WRITTEN.equals(problem)) {
                text.append(": write ").append(student.getClassName())
                        .append(" (docs/exercises.md)");
            }
            text.append('\n');
            return;
        }
        if (particle.hasLanded()) {
            TextFormat.appendFixed(text.append("landed at x = "), particle.getLandingX(), 2)
                    .append(" m after ");
            TextFormat.appendFixed(text, particle.getLandingSeconds(), 2).append(" s");
        } else {
            TextFormat.appendVector(text.append("P = "), particle.getParticle().position, 2)
                    .append(" m   |V| = ");
            TextFormat.appendFixed(text, Math.sqrt(state.velocity[0] * state.velocity[0]
                    + state.velocity[1] * state.velocity[1]
                    + state.velocity[2] * state.velocity[2]), 2).append(" m/s");
        }
        if (kind == Kind.SLIDE) {
            TextFormat.appendFixed(text.append("   |P - P_shared| = "), slideDifference, 6)
                    .append(" m");
        }
        appendCost(text);
        text.append('\n');
        if (forcesNote != null) {
            text.append("   ").append(forcesNote).append('\n');
        }
        appendSeenError(text);
        if (kind == Kind.SLIDE) {
            List<String> lines = slide.listing();
            for (int i = 0; i < lines.size(); ++i) {
                text.append("   slide:  ").append(lines.get(i)).append('\n');
            }
        }
    }

    /**
     * Say on the HUD, under the lane's first line, that the lane follows other forces than
     * the sphere runs now (the drag demo's swapped laws); set before the parts write their
     * lines.
     *
     * @param note one line without its newline, or null when the lane follows the sphere's
     */
    public void setForcesNote(String note) {
        forcesNote = note;
    }

    /** The next lane, from a new launch. */
    private void cycle() {
        DemoParameters parameters = demo.getParameters();
        int index = parameters.indexOf(PARAMETER);
        int next = (Math.round(parameters.getValue(index)) + 1) % KINDS.length;
        parameters.set(index, next);
        demo.restart();
    }

    /** Put a kind into the scene (at a launch). */
    private void select(Kind newKind) {
        kind = newKind;
        if (particle != null) {
            demo.relabel(particle, kind.label());
        }
        stepper = null;
        needsStart = true;
    }

    /** Start the lane's state, the slide code's and the exact path from the sphere's launch. */
    private void start() {
        needsStart = false;
        blewUp = false;
        hasErrors = false;
        Particle body = particle.getParticle();
        particle.copyLaunchPosition(scratchPosition);
        particle.copyLaunchVelocity(scratchVelocity);
        copyToState(scratchPosition, scratchVelocity);
        if (kind == Kind.SLIDE) {
            slide.start(scratchPosition, scratchVelocity, body.getMass());
        }
        if (kind == Kind.STUDENT) {
            if (student == null) {
                // once per class: a user's choice, not a step, so it may allocate
                student = new StudentRecipe(studentClass != null ? studentClass
                        : StudentRunner.className(StudentRecipe.SIMPLE_NAME),
                        studentLimitNanos);
            }
            student.restart();
        }
        exact.start(scratchPosition, scratchVelocity, body.getMass(),
                particle.stopsAtGround());
    }

    /** Advance the lane's state by h; false if it left the finite numbers. */
    private boolean advanceState(float stepSeconds) {
        if (kind == Kind.SLIDE) {
            slide.update(stepSeconds);
            copyToState(slide.position, slide.velocity);
            return state.isFinite();
        }
        if (kind == Kind.STUDENT) {
            if (unsupported) {
                return false;
            }
            studentGravity.set(coefficients[0], coefficients[1], coefficients[2]);
            return student.step(state, studentGravity, coefficients[3], coefficients[4],
                    coefficients[6], stepSeconds);
        }
        if (stepper == null) {
            return false;
        }
        try {
            stepper.step(state, stepSeconds);
        } catch (IllegalStateException nonFinite) {
            // the shared integrator refuses a non-finite step rather than spread NaN
            return false;
        }
        return state.isFinite();
    }

    /** Tell whether a force adds nothing at the followed sphere's state now. */
    private boolean addsNothing(Force force) {
        Particle source = followed.getParticle();
        scratchForce.zero();
        force.addForce(source, scratchForce);
        force.addFieldAcceleration(source, scratchForce);
        return scratchForce.x == 0f && scratchForce.y == 0f && scratchForce.z == 0f
                && force.dampingRate(source) == 0f && force.stiffness(source) == 0f;
    }

    private void copyToState(Vector3f position, Vector3f velocity) {
        double[] p = state.position;
        double[] v = state.velocity;
        p[0] = position.x;
        p[1] = position.y;
        p[2] = position.z;
        v[0] = velocity.x;
        v[1] = velocity.y;
        v[2] = velocity.z;
    }

    /**
     * Read the followed sphere's forces (g, m, b, c, k); build the report's model and stepper
     * again only when they changed (a coefficient moved live, a new launch).
     */
    private void refreshForces() {
        ParticleIntegrator integrator = followed.getIntegrator();
        java.util.Arrays.fill(coefficients, 0f);
        boolean known = true;
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force force = integrator.getForce(i);
            if (force instanceof Gravity) {
                ((Gravity) force).copyAcceleration(gravityNow);
                coefficients[0] += gravityNow.x;
                coefficients[1] += gravityNow.y;
                coefficients[2] += gravityNow.z;
            } else if (force instanceof LinearDrag) {
                coefficients[4] += ((LinearDrag) force).getCoefficient();
            } else if (force instanceof QuadraticDrag) {
                coefficients[5] += ((QuadraticDrag) force).getCoefficient();
            } else if (force instanceof Thrust) {
                coefficients[6] += ((Thrust) force).getMagnitude();
            } else if (!addsNothing(force)) {
                // (a force switched off adds nothing: a bug hunt's fault at 0, lecture/)
                known = false;
            }
        }
        coefficients[3] = particle.getParticle().getMass();
        // exercise 1's recipe has gravity, linear drag and thrust, no quadratic drag
        unsupported = !known || (kind == Kind.STUDENT && coefficients[5] != 0f);
        Scheme scheme = kind.scheme();
        if (scheme == null || !known) {
            return;
        }
        if (stepper != null && scheme == stepperScheme
                && java.util.Arrays.equals(coefficients, modelCoefficients)) {
            return;
        }
        // a change of the forces: a user's event, not a step's, so it may allocate
        System.arraycopy(coefficients, 0, modelCoefficients, 0, coefficients.length);
        model = new ForceModel(new double[] {coefficients[0], coefficients[1],
            coefficients[2]}, coefficients[3], coefficients[4], coefficients[5],
                coefficients[6]);
        stepper = scheme.create(model);
        stepperScheme = scheme;
    }

    /**
     * Note both errors after a step, for each sphere that flew in it: after a step in flight,
     * its state against the exact path now; in the step it landed, the contact point where it
     * stopped against the exact path at its landing time (what "at landing" names). The exact
     * path stops where it lands itself, as its ghost does.
     */
    private void noteErrors() {
        if (laneWasFlying) {
            if (particle.hasLanded()) {
                Vector3f contact = particle.getParticle().position;
                exact.copyPositionAt(particle.getLandingSeconds(), exactAtLanding);
                laneDx = contact.x - exactAtLanding[0];
                laneDy = contact.y - exactAtLanding[1];
            } else {
                laneDx = state.position[0] - exact.getPosition(0);
                laneDy = state.position[1] - exact.getPosition(1);
            }
            hasErrors = true;
        }
        if (followedWasFlying) {
            Vector3f main = followed.getParticle().position;
            if (followed.hasLanded()) {
                exact.copyPositionAt(followed.getLandingSeconds(), exactAtLanding);
                followedDx = main.x - exactAtLanding[0];
                followedDy = main.y - exactAtLanding[1];
            } else {
                if (kind == Kind.SLIDE) {
                    slideDifference = main.distance(slide.position);
                }
                followedDx = main.x - exact.getPosition(0);
                followedDy = main.y - exact.getPosition(1);
            }
            hasErrors = true;
        }
    }

    private void appendCost(StringBuilder text) {
        double nanos = costNanos[kind.ordinal()];
        if (kind == Kind.STUDENT && studentCostFailed) {
            text.append("   cost: not measured (the recipe threw on the meter's thread)");
            return;
        }
        if (Double.isNaN(nanos)) {
            text.append("   cost: measuring");
            return;
        }
        TextFormat.appendFixed(text.append("   "), nanos, 0).append(" ns");
        if (kind == Kind.SLIDE || kind == Kind.STUDENT) {
            TextFormat.appendFixed(text.append(", "), costBytes[kind.ordinal()], 0)
                    .append(" B");
        }
        text.append(" per step (measured on this machine)");
    }

    private void appendSeenError(StringBuilder text) {
        text.append("Seen error");
        if (particle.hasLanded()) {
            text.append(" at landing");
        }
        text.append(" (visible: 1 px or 1 radius):  ");
        if (blewUp) {
            text.append("the lane's step blew up (h beyond its stability limit);  ");
        } else if (unsupported && kind != Kind.SLIDE) {
            text.append("these forces are not among the report's models;  ");
        } else {
            appendError(text.append("lane "), laneDx, laneDy, true).append(";  ");
        }
        // the followed sphere, stepped by the shared integrator (its own line has the metres)
        appendError(text.append("shared "), followedDx, followedDy, false).append('\n');
    }

    private StringBuilder appendError(StringBuilder text, double dx, double dy,
            boolean withMetres) {
        if (!hasErrors) {
            return text.append("-");
        }
        double metres = Math.hypot(dx, dy);
        PlaneView view = demo.getWindow().getPlaneView();
        double pixels = ScreenError.pixels(view, dx, dy);
        double radii = ScreenError.radii(metres, radiusMetres);
        if (withMetres) {
            TextFormat.appendFixed(text, metres, 4).append(" m, ");
        }
        TextFormat.appendFixed(text, pixels, 2).append(" px, ");
        TextFormat.appendFixed(text, radii, 2).append(" radii: ");
        return text.append(ScreenError.isVisible(pixels, radii) ? "visible" : "invisible");
    }

    /** Start measuring the cost of the lane now, once per kind, on a background thread. */
    private void measureCostOnce() {
        int index = kind.ordinal();
        if (costAsked[index] || (kind.scheme() != null && model == null)) {
            return;
        }
        if (kind == Kind.STUDENT && (student == null || blewUp || unsupported || needsStart)) {
            // measured only once the recipe has stepped: a recipe that never returns would
            // keep the meter's thread busy for good
            return;
        }
        costAsked[index] = true;
        Kind measured = kind;
        ForceModel forces = model;
        float mass = particle.getParticle().getMass();
        particle.copyLaunchPosition(scratchPosition);
        particle.copyLaunchVelocity(scratchVelocity);
        Vector3f launchPosition = scratchPosition.clone();
        Vector3f launchVelocity = scratchVelocity.clone();
        float stepSeconds = demo.getClock().getStepSeconds();
        float[] studentForces = coefficients.clone();
        String studentName = student == null ? null : student.getClassName();
        Thread thread = new Thread(() -> {
            if (measured == Kind.STUDENT) {
                measureStudent(studentName, studentForces, launchPosition, launchVelocity,
                        stepSeconds);
            } else {
                measure(measured, forces, launchPosition, launchVelocity, mass, stepSeconds);
            }
        }, "lane cost " + measured.id());
        thread.setDaemon(true);
        thread.start();
    }

    /** The meter's run: the lane's method alone, from the launch, 64 steps a call. */
    private void measure(Kind measured, ForceModel forces, Vector3f launchPosition,
            Vector3f launchVelocity, float mass, float stepSeconds) {
        CostMeter meter = new CostMeter(CostMeter.Budget.QUICK);
        CostMeter.Measurement result;
        if (measured == Kind.SLIDE) {
            SlideCode code = slideFactory.get();
            result = meter.measure(units -> {
                code.start(launchPosition, launchVelocity, mass);
                for (int n = 0; n < units; ++n) {
                    code.update(stepSeconds);
                }
                return code.position;
            }, COST_STEPS);
        } else {
            Stepper alone = measured.scheme().create(forces);
            MotionState launchState = new MotionState(launchPosition.x, launchPosition.y,
                    launchVelocity.x, launchVelocity.y);
            MotionState work = new MotionState();
            result = meter.measure(units -> {
                work.set(launchState);
                alone.advance(work, stepSeconds, units);
                return work;
            }, COST_STEPS);
        }
        costBytes[measured.ordinal()] = result.bytesPerUnit();
        costNanos[measured.ordinal()] = result.nanosPerUnit();
    }

    /**
     * The meter's run of the student's recipe: a fresh instance of the class on this thread,
     * from the launch, 64 steps a call. Anything it throws marks the cost unmeasured.
     */
    private void measureStudent(String className, float[] forces, Vector3f launchPosition,
            Vector3f launchVelocity, float stepSeconds) {
        int index = Kind.STUDENT.ordinal();
        try {
            RecipeExercise recipe = Class.forName(className)
                    .asSubclass(RecipeExercise.class).getDeclaredConstructor().newInstance();
            Vector3f g = new Vector3f(forces[0], forces[1], forces[2]);
            Vector3f position = new Vector3f();
            Vector3f velocity = new Vector3f();
            CostMeter meter = new CostMeter(CostMeter.Budget.QUICK);
            CostMeter.Measurement result = meter.measure(units -> {
                position.set(launchPosition);
                velocity.set(launchVelocity);
                for (int n = 0; n < units; ++n) {
                    recipe.step(position, velocity, forces[3], g, forces[4], forces[6],
                            stepSeconds);
                }
                return position;
            }, COST_STEPS);
            costBytes[index] = result.bytesPerUnit();
            costNanos[index] = result.nanosPerUnit();
        } catch (Throwable e) {
            // the student's code, on the meter's own thread: its failure is the lane's line
            studentCostFailed = true;
        }
    }

    /** The lane's state for the replay ring. */
    private StateRecord record() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return STATE_INTS;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putBoolean(needsStart);
                slab.putBoolean(blewUp);
                for (int i = 0; i < 3; ++i) {
                    slab.putDouble(state.position[i]);
                    slab.putDouble(state.velocity[i]);
                }
                slab.putVector(slide.position);
                slab.putVector(slide.velocity);
                exact.writeState(slab);
                slab.putDouble(laneDx);
                slab.putDouble(laneDy);
                slab.putDouble(followedDx);
                slab.putDouble(followedDy);
                slab.putDouble(slideDifference);
                slab.putBoolean(hasErrors);
                slab.putBoolean(unsupported);
            }

            @Override
            public void readState(StateSlab slab) {
                needsStart = slab.getBoolean();
                blewUp = slab.getBoolean();
                for (int i = 0; i < 3; ++i) {
                    state.position[i] = slab.getDouble();
                    state.velocity[i] = slab.getDouble();
                }
                slab.getVector(slide.position);
                slab.getVector(slide.velocity);
                exact.readState(slab);
                laneDx = slab.getDouble();
                laneDy = slab.getDouble();
                followedDx = slab.getDouble();
                followedDy = slab.getDouble();
                slideDifference = slab.getDouble();
                hasErrors = slab.getBoolean();
                unsupported = slab.getBoolean();
            }
        };
    }
}
