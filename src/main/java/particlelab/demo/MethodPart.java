package particlelab.demo;

import com.jme3.math.Vector3f;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * How a demo's spheres step ({@code --set method=...}, a what-if fork's change): a visible,
 * named choice, never a silent one.
 * <ul>
 * <li>{@code recipe} (the default): the lecture's recipe, the one integrator every demo
 * particle uses ({@link ParticleIntegrator}: {@code V ← V + h·a}, then {@code P ← P + h·V}
 * with the new V), untouched: this part then only hands each sphere its forces.</li>
 * <li>{@code euler}: forward (explicit) Euler, the order of another book and of the pull
 * demo's bug hunt ({@code lecture/LectureFaults.PositionBeforeVelocity}): {@code P ← P + h·V}
 * with the old V, then {@code V ← V + h·a}, with {@code a = g + F/m} from the sphere's own
 * forces (the recipe's first line, {@link ParticleIntegrator#acceleration}), in float.</li>
 * </ul>
 * Forward Euler runs inside the world's step like every motion: before the step this part
 * computes {@code V_{n+1} = V_n + h·a(V_n)} and gives the sphere a forceless integrator, whose
 * step is exactly {@code P ← P + h·V_n} (V plus {@code h·0} stays V), so the ground's swept
 * test sees the method's own segment; before the next step the sphere takes its
 * {@code V_{n+1}}. Between steps the sphere therefore shows the velocity it last moved with,
 * {@code V_n}, one step behind the method's {@code V_{n+1}}, which waits here (and in the
 * replay ring, with the flag that says it waits).
 *
 * <p>The demo may give a sphere other forces while it runs ({@link #setForces}: the drag
 * demo's swapped laws); its exact ghost, which follows the forces the sphere was launched
 * with, is then hidden, and the HUD compares nothing with it. Per step and per frame this
 * allocates nothing.
 */
public final class MethodPart implements DemoPart {

    /** The parameter's command-line name. */
    public static final String PARAMETER = "method";
    /** The lecture's recipe: semi-implicit Euler, the default. */
    public static final int RECIPE = 0;
    /** Forward Euler: P with the old V, then V. */
    public static final int FORWARD_EULER = 1;
    /** The methods by {@code --set method=} name, in key order. */
    private static final String[] NAMES = {"recipe", "euler"};
    /** The methods as the HUD names them. */
    private static final String[] LABELS = {"the lecture's recipe",
        "forward Euler: P += h·V with the old V, then V += h·a (not the lecture's recipe)"};
    /** The most spheres one demo hands this part. */
    private static final int MAX_SPHERES = 4;

    /** The forceless step: {@code V + h·0 = V}, then {@code P + h·V}. */
    private final ParticleIntegrator coast = new ParticleIntegrator();
    private final DemoParticle[] spheres = new DemoParticle[MAX_SPHERES];
    /** The forces each sphere runs with now (its own unless the demo said otherwise). */
    private final ParticleIntegrator[] forces = new ParticleIntegrator[MAX_SPHERES];
    /** Forward Euler's {@code V_{n+1}}, waiting for the next step (m/s). */
    private final Vector3f[] nextVelocity = new Vector3f[MAX_SPHERES];
    /** The sphere shows {@code V_n}; {@link #nextVelocity} holds its next velocity. */
    private final boolean[] waiting = new boolean[MAX_SPHERES];
    /** Scratch: a at the step's start (m/s²). */
    private final Vector3f acceleration = new Vector3f();
    private DemoState demo;
    private int count;
    private int method = RECIPE;

    /** Create the part; the demo then hands it its spheres ({@link #drive}). */
    public MethodPart() {
        for (int i = 0; i < MAX_SPHERES; ++i) {
            nextVelocity[i] = new Vector3f();
        }
    }

    /**
     * Step a sphere by the method chosen. Call from the demo's {@code createScene()}, the part
     * having been added with {@link DemoState#addPart}.
     *
     * @param sphere one of the demo's particles (not null)
     * @return sphere
     */
    public DemoParticle drive(DemoParticle sphere) {
        if (demo == null || sphere == null || count == MAX_SPHERES) {
            throw new IllegalStateException("the method part drives up to " + MAX_SPHERES
                    + " spheres of the demo it was added to, but was given " + sphere);
        }
        spheres[count] = sphere;
        forces[count] = sphere.getIntegrator();
        ++count;
        install();
        return sphere;
    }

    /**
     * Give a sphere other forces from its next step on (the drag demo's swapped laws). Called
     * before the step, from the demo's {@code beforeStep}; allocates nothing.
     *
     * @param sphere a sphere handed to {@link #drive} (not null)
     * @param newForces the integrator whose forces move it now (not null)
     */
    public void setForces(DemoParticle sphere, ParticleIntegrator newForces) {
        for (int i = 0; i < count; ++i) {
            if (spheres[i] == sphere) {
                forces[i] = newForces;
                sphere.setForcesNow(newForces);
                install();
                return;
            }
        }
        throw new IllegalArgumentException("the method part does not drive " + sphere);
    }

    /**
     * Return the method the spheres step with.
     *
     * @return {@link #RECIPE} or {@link #FORWARD_EULER}
     */
    public int getMethod() {
        return method;
    }

    /**
     * Copy the velocity a sphere takes into its next step: forward Euler's waiting
     * {@code V_{n+1}}, otherwise its own.
     *
     * @param sphere a sphere handed to {@link #drive} (not null)
     * @param storeResult storage for the velocity (in m/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyNextVelocity(DemoParticle sphere, Vector3f storeResult) {
        for (int i = 0; i < count; ++i) {
            if (spheres[i] == sphere) {
                return storeResult.set(waiting[i] ? nextVelocity[i]
                        : sphere.getParticle().velocity);
            }
        }
        throw new IllegalArgumentException("the method part does not drive " + sphere);
    }

    @Override
    public void attach(DemoState owner) {
        demo = owner;
    }

    /** Declare {@code --set method=recipe|euler}: live, from the next step on. */
    @Override
    public void declareParameters(DemoParameters parameters) {
        // "integrator", short: the drag panel's 15 rows fit at 1280x720 only unwrapped
        parameters.add(DemoParameter.choice(PARAMETER, "integrator", NAMES, RECIPE,
                DemoParameter.Applies.LIVE, value -> {
                    method = Math.round(value);
                    install();
                }));
    }

    /**
     * Before the world's step: each sphere in flight gets the velocity it moves with and the
     * integrator that moves it; forward Euler's next velocity is computed here. Allocates
     * nothing.
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    @Override
    public void beforeStep(float stepSeconds) {
        for (int i = 0; i < count; ++i) {
            DemoParticle sphere = spheres[i];
            Particle particle = sphere.getParticle();
            if (sphere.isHeld()) {
                // landed (the ground holds it) or held by the demo: nothing waits
                waiting[i] = false;
                continue;
            }
            if (waiting[i]) {
                particle.velocity.set(nextVelocity[i]);
                waiting[i] = false;
            }
            if (method == FORWARD_EULER) {
                // V_{n+1} = V_n + h·a(V_n); the world's forceless step moves P with V_n
                forces[i].acceleration(particle, acceleration);
                Vector3f velocity = particle.velocity;
                nextVelocity[i].set(velocity.x + stepSeconds * acceleration.x,
                        velocity.y + stepSeconds * acceleration.y,
                        velocity.z + stepSeconds * acceleration.z);
                waiting[i] = true;
            }
        }
        install();
    }

    @Override
    public void onRestart() {
        for (int i = 0; i < count; ++i) {
            waiting[i] = false;
        }
    }

    /**
     * A sphere whose forces are not those its exact path follows: its ghost hidden, nothing
     * compared with it on the HUD. Allocates nothing.
     */
    @Override
    public void afterFrame() {
        for (int i = 0; i < count; ++i) {
            int index = demo.getParticles().indexOf(spheres[i]);
            demo.getExactGhosts().setOtherForces(index,
                    forces[i] != spheres[i].getPathIntegrator());
        }
    }

    /** Another method than the recipe: one line that names it. */
    @Override
    public void writeHudLines(StringBuilder text) {
        if (method != RECIPE) {
            text.append("Method (").append(PARAMETER).append("): ").append(LABELS[method])
                    .append('\n');
        }
    }

    /** The waiting velocities, with their flags: what the next step reads. */
    @Override
    public StateRecord stateRecord() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 4 * count;
            }

            @Override
            public void writeState(StateSlab slab) {
                for (int i = 0; i < count; ++i) {
                    slab.putBoolean(waiting[i]);
                    slab.putVector(nextVelocity[i]);
                }
            }

            @Override
            public void readState(StateSlab slab) {
                for (int i = 0; i < count; ++i) {
                    waiting[i] = slab.getBoolean();
                    slab.getVector(nextVelocity[i]);
                }
            }
        };
    }

    /** Give each sphere's body the integrator the method and its forces say. */
    private void install() {
        if (count == 0) {
            return;
        }
        World world = demo.getWorld();
        for (int i = 0; i < count; ++i) {
            ParticleIntegrator moving = method == RECIPE ? forces[i] : coast;
            if (spheres[i].getBody().getIntegrator() != moving) {
                world.setIntegrator(spheres[i].getBody(), moving);
            }
        }
    }
}
