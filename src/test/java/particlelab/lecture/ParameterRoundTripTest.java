package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.app.DemoCatalog;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoState;
import particlelab.demo.LensPart;
import particlelab.demo.RateLanes;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SlideFormDrag;
import particlelab.physics.Spring;
import particlelab.physics.Thrust;
import particlelab.world.Body;
import particlelab.world.ClipReader;
import particlelab.world.CollisionRule;
import particlelab.world.ContactResponse;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SphereRule;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * One source of truth per parameter (issue 30 §2): every declared parameter of every demo,
 * set to a value inside its range that is on no key step (for a choice: another name), is the
 * value the physics then runs with, read back from the object that uses it (a force, a
 * contact response, a launched body, the clock), never from the panel. Both ways in: before
 * the start, as {@code --set} does, and live, after the start, as the panel does (a
 * next-launch value after a reset). No parameter has a grid: a value off the keys' steps is
 * kept as given, not rounded. The demos are made with {@code new}: no jME application.
 */
class ParameterRoundTripTest {

    /** Where in its range the value set lies: on no key step of any declared parameter. */
    private static final float SHARE_OF_RANGE = 0.3719f;
    /**
     * How far a value read back through a launch velocity may be from the value set: the
     * velocity is speed·(cos θ, sin θ) rounded to floats, and the speed and angle come back
     * through a hypot and an atan2 in double, so a few float roundings (2⁻²⁴ ≈ 6e-8 each)
     * relative, well under 1e-6; an angle in degrees, of at most 85, to 1e-4.
     */
    private static final float RELATIVE_LAUNCH_TOLERANCE = 1e-6f;
    private static final float ANGLE_TOLERANCE_DEGREES = 1e-4f;

    /** A parameter read back from the physics, with the tolerance its path needs. */
    private static final class Reader {
        final Function<DemoState, Float> read;
        final float tolerance;
        final boolean relative;

        Reader(Function<DemoState, Float> read, float tolerance, boolean relative) {
            this.read = read;
            this.tolerance = tolerance;
            this.relative = relative;
        }
    }

    /** Readers by "demo/parameter", "* /parameter" for every demo (the shared ones). */
    private static final Map<String, Reader> READERS = new TreeMap<>();

    static {
        // Shared by every demo: the clock's step, the energy ledger's switch.
        exact("*/h", demo -> demo.getClock().getStepSeconds());
        exact("*/energy", demo -> demo.getEnergyPart().isShown() ? 1f : 0f);
        // The comparison lane of the free-flight demos: the kind the lane flies.
        for (String name : new String[] {"uniform", "pull", "drag", "thrust"}) {
            exact(name + "/lane", demo -> (float) demo.getParameters().get(
                    demo.getParameters().indexOf("lane")).indexOfChoice(lane(demo)));
            // The derivative lens's switch.
            exact(name + "/lens", demo -> lens(demo).isOn() ? 1f : 0f);
            // LaunchControl: the launched sphere's velocity and mass, every gravity's g.
            READERS.put(name + "/speed", new Reader(demo -> (float) Math.hypot(
                    launched(demo).x, launched(demo).y), RELATIVE_LAUNCH_TOLERANCE, true));
            READERS.put(name + "/angle", new Reader(demo -> (float) Math.toDegrees(
                    Math.atan2(launched(demo).y, launched(demo).x)),
                    ANGLE_TOLERANCE_DEGREES, false));
            exact(name + "/mass", demo -> demo.getParticles().get(0).getParticle()
                    .getMass());
            exact(name + "/g", ParameterRoundTripTest::gravity);
        }
        // The pull demo's rate lanes (issue 33 §1): whether they fly, the distribution the
        // histogram draws frame times from, and its width.
        exact("pull/rates", demo -> rates(demo).getJitter() != null
                ? 2f + rates(demo).getJitter().ordinal() : rates(demo).isOn() ? 1f : 0f);
        exact("pull/jitter_ms", demo -> rates(demo).getJitterWidthMs());
        exact("drag/b", demo -> one(demo, LinearDrag.class, LinearDrag::getCoefficient));
        exact("drag/c", demo -> ((DragDemo) demo).isSlideForm()
                ? one(demo, SlideFormDrag.class, SlideFormDrag::getCoefficient)
                : one(demo, QuadraticDrag.class, QuadraticDrag::getCoefficient));
        // The law is which force the quadratic sphere carries.
        exact("drag/law", demo -> count(demo, SlideFormDrag.class) > 0 ? 1f : 0f);
        // The bug hunt (issue 34): which force carries the coefficient, and the pick's seed.
        exact("drag/fault", demo -> !((DragDemo) demo).isSlideForm()
                && one(demo, SlideFormDrag.class, SlideFormDrag::getCoefficient) > 0f ? 1f : 0f);
        exact("drag/seed", demo -> ((DragDemo) demo).getFaultSeed());
        // The method: forward Euler's spheres are moved by a forceless integrator (P += h·V
        // with the old V), the recipe's by their forces.
        exact("drag/method", demo -> demo.getWorld().getBody(0).getIntegrator()
                .countForces() == 0 ? 1f : 0f);
        // The swapped laws: the linear sphere's body carries quadratic drag.
        exact("drag/drag", demo -> count(demo.getWorld().getBody(1).getIntegrator(),
                QuadraticDrag.class) > 0 ? 1f : 0f);
        exact("thrust/b", demo -> one(demo, LinearDrag.class, LinearDrag::getCoefficient));
        exact("thrust/k", demo -> one(demo, Thrust.class, Thrust::getMagnitude));
        exact("thrust/fault", demo -> one(demo, LectureFaults.ThrustAlongAnother.class,
                LectureFaults.ThrustAlongAnother::getMagnitude) > 0f ? 1f
                : one(demo, LectureFaults.UnnormalisedThrust.class,
                        LectureFaults.UnnormalisedThrust::getMagnitude) > 0f ? 2f : 0f);
        exact("thrust/seed", demo -> ((ThrustDemo) demo).getFaultSeed());
        // pull's fault is the order the twin steps in
        exact("pull/fault", demo -> ((GravitationalPullDemo) demo).isTwinPositionFirst()
                ? 1f : 0f);
        exact("pull/seed", demo -> ((GravitationalPullDemo) demo).getFaultSeed());
        // aiming's fault is the listing's loop flying in the shot (code stays as set)
        exact("aiming/fault", demo -> ((HelloAimingDemo) demo).isSlideInShot()
                && ((HelloAimingDemo) demo).getCode() == HelloAimingDemo.RECIPE_CODE ? 1f : 0f);
        exact("aiming/seed", demo -> ((HelloAimingDemo) demo).getFaultSeed());
        exact("spring/k", demo -> one(demo, Spring.class, Spring::getSpringConstant));
        // The damped spring's c; the undamped one keeps 0 (read by its own force).
        exact("spring/c", demo -> {
            float most = 0f;
            for (Spring spring : forces(demo, Spring.class)) {
                most = Math.max(most, spring.getDamping());
            }
            return most;
        });
        exact("wind/w", demo -> ((WindDemo) demo).getWind().copyWindVelocity(new Vector3f()).x);
        exact("bounce/e", demo -> restitution(demo, SurfaceRule.class));
        exact("bounce/threshold", demo -> (float) threshold(demo));
        exact("bounce/fix", demo -> impulse(demo, SurfaceRule.class).isRestingFix() ? 1f : 0f);
        exact("bounce/detection", demo -> ((BounceDemo) demo).getDetection()
                == Detection.SWEPT ? 0f : 1f);
        // The balls' rule has a response of the demo's own, which keeps e.
        exact("collisions/e", demo -> ((CollisionsDemo) demo).getRestitution());
        exact("collisions/preset", demo -> (float) ((CollisionsDemo) demo).getPreset()
                .ordinal());
        // The physics lane's response: the impulse the pair rule hands that lane's contacts.
        exact("clip/e", demo -> ((ClipResponseDemo) demo).getRestitution());
        READERS.put("clip/speed", new Reader(demo -> rocket(demo)
                .getParticle().velocity.length(), RELATIVE_LAUNCH_TOLERANCE, true));
        READERS.put("clip/angle", new Reader(demo -> {
            Vector3f v = rocket(demo).getParticle().velocity;
            return (float) Math.toDegrees(Math.atan2(v.y, v.x));
        }, ANGLE_TOLERANCE_DEGREES, false));
        exact("clip/m_rocket", demo -> rocket(demo).getMass());
        exact("clip/m_target", demo -> clipTarget(demo).getMass());
        exact("clip/clip", demo -> (float) indexOfClip((ClipResponseDemo) demo));
        // ω = |ω|·axis, a unit axis off the coordinate axes: three products rounded to floats
        // and a square root, so the length is |ω| to a few float roundings (≈ 6e-8 each).
        READERS.put("rotation/omega", new Reader(demo -> demo.getWorld().getBody(0)
                .getRigidBody().angularVelocity.length(), RELATIVE_LAUNCH_TOLERANCE, true));
        exact("racket/method", demo -> (float) ((TennisRacketDemo) demo).getShownMethod());
        exact("racket/gyro", demo -> demo.getWorld().getBody(0).getRotationIntegrator()
                .isGyroscopic() ? 1f : 0f);
        READERS.put("targets/angle", new Reader(demo -> {
            Vector3f v = fastest(demo);
            return (float) Math.toDegrees(Math.atan2(v.y, v.x));
        }, ANGLE_TOLERANCE_DEGREES, false));
        exact("targets/pane", demo -> ((TargetsDemo) demo).isPaneGhost() ? 0f : 1f);
        exact("aiming/vx", demo -> ((HelloAimingDemo) demo).getHorizontalSpeed());
        exact("aiming/g", ParameterRoundTripTest::gravity);
        exact("aiming/aim", demo -> (float) ((HelloAimingDemo) demo).getFiring());
        exact("aiming/code", demo -> (float) ((HelloAimingDemo) demo).getCode());
        exact("iterate/strategy", demo -> (float) demo.getParameters().get(
                demo.getParameters().indexOf("strategy")).indexOfChoice(
                ((IterativeAimingDemo) demo).getStrategy().cliName()));
        exact("iterate/drag", demo -> (float) ((IterativeAimingDemo) demo).getDrag()
                .ordinal());
        exact("iterate/instant", demo -> ((IterativeAimingDemo) demo).isInstant() ? 1f : 0f);
        exact("iterate/predictor", demo -> ((IterativeAimingDemo) demo).isMismatch() ? 1f
                : 0f);
        exact("iterate/duel", demo -> ((IterativeAimingDemo) demo).isDuelOn() ? 1f : 0f);
        exact("cheat/speed", demo -> (float) indexOfSpeed((FastBulletsDemo) demo));
        exact("cheat/shot", demo -> (float) ((FastBulletsDemo) demo).getShown());
    }

    static Stream<String> demoNames() {
        return DemoCatalog.names().stream();
    }

    /** Set before the start, as {@code particle-lab demo NAME --set NAME=VALUE} does. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void everyParameterSetBeforeTheStartIsTheValueThePhysicsRunsWith(String name) {
        int count = create(name).getParameters().size();
        for (int i = 0; i < count; ++i) {
            DemoState demo = create(name);
            DemoParameter parameter = demo.getParameters().get(i);
            float value = offGridValue(parameter);
            demo.getParameters().set(parameter.getName(), value);
            demo.getWorld();
            assertReadsBack(name, demo, parameter, value, "set before the start");
        }
    }

    /** Set live, after the start, as the panel does; a next-launch value after a reset. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void everyParameterSetLiveIsTheValueThePhysicsRunsWith(String name) {
        int count = create(name).getParameters().size();
        for (int i = 0; i < count; ++i) {
            DemoState demo = create(name);
            demo.getWorld();
            DemoParameter parameter = demo.getParameters().get(i);
            float value = offGridValue(parameter);
            demo.getParameters().set(parameter.getName(), value);
            if (parameter.getApplies() == DemoParameter.Applies.NEXT_LAUNCH) {
                demo.restart();
            }
            assertReadsBack(name, demo, parameter, value, "set live");
        }
    }

    private static void assertReadsBack(String name, DemoState demo, DemoParameter parameter,
            float value, String how) {
        Reader reader = READERS.get(name + "/" + parameter.getName());
        if (reader == null) {
            reader = READERS.get("*/" + parameter.getName());
        }
        assertNotNull(reader, name + ": no reader of " + parameter.getName()
                + " from the physics; add one to READERS");
        float read = reader.read.apply(demo);
        float tolerance = reader.relative ? reader.tolerance * Math.abs(value)
                : reader.tolerance;
        assertEquals(value, read, tolerance, name + ": " + parameter.getName() + " = "
                + value + " " + how + ", the physics runs with " + read);
        assertNotEquals(parameter.getDefault(), value, "the value tested is not the default");
    }

    /**
     * A value inside the range on no key step: for a number, 37.19 % of the way from min to
     * max (at least a hundredth of a step from a whole step, checked); for a choice, the name
     * after the default.
     */
    private static float offGridValue(DemoParameter parameter) {
        if (parameter.isChoice()) {
            return (Math.round(parameter.getDefault()) + 1) % parameter.countChoices();
        }
        float value = parameter.getMin()
                + SHARE_OF_RANGE * (parameter.getMax() - parameter.getMin());
        float steps = (value - parameter.getMin()) / parameter.getStep();
        assertTrue(Math.abs(steps - Math.round(steps)) > 0.01f, parameter.getName() + ": "
                + value + " lies on a key step");
        return value;
    }

    private static DemoState create(String name) {
        return DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
    }

    private static void exact(String key, Function<DemoState, Float> read) {
        READERS.put(key, new Reader(read, 0f, false));
    }

    private static String lane(DemoState demo) {
        if (demo instanceof UniformMotionDemo) {
            return ((UniformMotionDemo) demo).getLane().getKind().id();
        } else if (demo instanceof GravitationalPullDemo) {
            return ((GravitationalPullDemo) demo).getLane().getKind().id();
        } else if (demo instanceof DragDemo) {
            return ((DragDemo) demo).getLane().getKind().id();
        }
        return ((ThrustDemo) demo).getLane().getKind().id();
    }


    private static RateLanes rates(DemoState demo) {
        return ((GravitationalPullDemo) demo).getRates();
    }

    private static LensPart lens(DemoState demo) {
        if (demo instanceof UniformMotionDemo) {
            return ((UniformMotionDemo) demo).getLens();
        } else if (demo instanceof GravitationalPullDemo) {
            return ((GravitationalPullDemo) demo).getLens();
        } else if (demo instanceof DragDemo) {
            return ((DragDemo) demo).getLens();
        }
        return ((ThrustDemo) demo).getLens();
    }

    /** The first particle's velocity: the launch velocity right after a reset (m/s). */
    private static Vector3f launched(DemoState demo) {
        return demo.getParticles().get(0).getParticle().velocity;
    }

    /** The velocity of the fastest body in the world (m/s). */
    private static Vector3f fastest(DemoState demo) {
        World world = demo.getWorld();
        Vector3f best = Vector3f.ZERO;
        for (int i = 0; i < world.countBodies(); ++i) {
            Vector3f v = world.getBody(i).getParticle().velocity;
            if (v.lengthSquared() > best.lengthSquared()) {
                best = v;
            }
        }
        return best;
    }

    /** Every force of a class that the world's bodies' integrators hold. */
    private static <F extends Force> List<F> forces(DemoState demo, Class<F> type) {
        List<F> found = new ArrayList<>();
        World world = demo.getWorld();
        for (int i = 0; i < world.countBodies(); ++i) {
            ParticleIntegrator integrator = world.getBody(i).getIntegrator();
            for (int k = 0; k < integrator.countForces(); ++k) {
                Force force = integrator.getForce(k);
                if (type.isInstance(force) && !found.contains(force)) {
                    found.add(type.cast(force));
                }
            }
        }
        return found;
    }

    private static int count(ParticleIntegrator integrator, Class<? extends Force> type) {
        int found = 0;
        for (int k = 0; k < integrator.countForces(); ++k) {
            found += type.isInstance(integrator.getForce(k)) ? 1 : 0;
        }
        return found;
    }

    private static int count(DemoState demo, Class<? extends Force> type) {
        return forces(demo, type).size();
    }

    /** The one value every force of a class holds (they must agree). */
    private static <F extends Force> float one(DemoState demo, Class<F> type,
            Function<F, Float> read) {
        List<F> found = forces(demo, type);
        assertNotEquals(0, found.size(), "no " + type.getSimpleName() + " in the world");
        float value = read.apply(found.get(0));
        for (F force : found) {
            assertEquals(value, read.apply(force), type.getSimpleName() + "s disagree");
        }
        return value;
    }

    /** g, as every gravity force of the world gives it (they must agree). */
    private static float gravity(DemoState demo) {
        return one(demo, Gravity.class, g -> -g.copyAcceleration(new Vector3f()).y);
    }

    private static CollisionRule rule(DemoState demo, Class<? extends CollisionRule> type) {
        World world = demo.getWorld();
        for (int i = 0; i < world.countRules(); ++i) {
            if (type.isInstance(world.getRule(i))) {
                return world.getRule(i);
            }
        }
        throw new AssertionError("no " + type.getSimpleName() + " in the world");
    }

    private static ImpulseResponse impulse(DemoState demo, Class<? extends CollisionRule> type) {
        CollisionRule rule = rule(demo, type);
        ContactResponse response = rule instanceof SurfaceRule
                ? ((SurfaceRule) rule).getResponse() : ((SphereRule) rule).getResponse();
        return (ImpulseResponse) response;
    }

    private static float restitution(DemoState demo, Class<? extends CollisionRule> type) {
        return impulse(demo, type).getRestitution();
    }

    private static int threshold(DemoState demo) {
        float speed = impulse(demo, SurfaceRule.class).getThresholdSpeed();
        for (int i = 0; i < BounceDemo.THRESHOLDS.length; ++i) {
            if (BounceDemo.THRESHOLDS[i] == speed) {
                return i;
            }
        }
        return -1;
    }

    /** The clip demo's physics-lane rocket. */
    private static Body rocket(DemoState demo) {
        return ((ClipResponseDemo) demo).body(ClipResponseDemo.PHYSICS_LANE,
                ClipResponseDemo.ROCKET);
    }

    /** The clip demo's physics-lane target. */
    private static Body clipTarget(DemoState demo) {
        return ((ClipResponseDemo) demo).body(ClipResponseDemo.PHYSICS_LANE,
                ClipResponseDemo.TARGET);
    }

    private static int indexOfClip(ClipResponseDemo demo) {
        // The clip the lane plays, told apart by the name it was read as.
        for (int i = 0; i < ClipResponseDemo.CLIP_NAMES.length; ++i) {
            String file = "clips/" + ClipResponseDemo.CLIP_NAMES[i] + ".clip";
            if (ClipReader.readResource(file).getName().equals(demo.getClip().getName())) {
                return i;
            }
        }
        return -1;
    }

    private static int indexOfSpeed(FastBulletsDemo demo) {
        for (int i = 0; i < FastBulletsDemo.SPEEDS.length; ++i) {
            if (FastBulletsDemo.SPEEDS[i] == demo.getSpeed()) {
                return i;
            }
        }
        return -1;
    }
}
