package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.Draggable;
import particlelab.demo.Presentation;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;
import particlelab.view.TextFormat;

/**
 * Demo "wind": the worked example of "write your own demo" (see the README). A new force and
 * a demo that uses it, in one file. Builds upon gravitational pull and the drag demo.
 *
 * <p>Wind is drag against moving air: the air pushes on the ball in proportion to the ball's
 * velocity <em>relative to the air</em>, {@code F = b·(W − V)}, where W is the wind's
 * velocity. In still air ({@code W = 0}) this is the linear drag of demo 3.
 *
 * <p>What to watch for: two balls launched together with {@code V0 = (10, 10, 0)} m/s, one in
 * still air, one in the wind. A headwind (W pointing back at the gun) shortens the flight and
 * can even blow the ball backwards as it falls; a tailwind carries it farther. The ball's
 * horizontal speed drifts toward the wind's, so a falling ball ends up moving with the air.
 */
public final class WindDemo extends DemoState {

    /**
     * Wind: linear drag relative to moving air, {@code F = b·(W − V)}.
     */
    public static final class Wind implements Force {

        private final Vector3f windVelocity = new Vector3f();
        private final float coefficient;

        /**
         * Create wind.
         *
         * @param windVelocity W, the air's velocity (in m/s, finite, not null, copied)
         * @param coefficient b (in N·s/m, finite, &ge;0)
         */
        public Wind(Vector3f windVelocity, float coefficient) {
            setWindVelocity(windVelocity);
            this.coefficient = Validate.nonNegative(coefficient, "wind drag b (N*s/m)");
        }

        /**
         * Alter the wind.
         *
         * @param newVelocity W (in m/s, finite, not null, not modified)
         */
        public void setWindVelocity(Vector3f newVelocity) {
            windVelocity.set(Validate.finite(newVelocity, "wind velocity W (m/s)"));
        }

        /**
         * Copy the wind's velocity into storeResult.
         *
         * @param storeResult storage for the result (not null, modified)
         * @return storeResult
         */
        public Vector3f copyWindVelocity(Vector3f storeResult) {
            return storeResult.set(windVelocity);
        }

        @Override
        public void addForce(Particle particle, Vector3f netForce) {
            // F = b (W - V), written without temporaries: F += b W, then F -= b V.
            netForce.scaleAdd(coefficient, windVelocity, netForce);
            netForce.scaleAdd(-coefficient, particle.velocity, netForce);
        }

        @Override
        public float dampingRate(Particle particle) {
            // Like linear drag: the speed relative to the air decays at b/m.
            return coefficient / particle.getMass();
        }

        @Override
        public String describe() {
            return "F = " + coefficient + "·(W - V), W = (" + windVelocity.x + ", "
                    + windVelocity.y + ", " + windVelocity.z + ") m/s";
        }
    }

    /** How strongly the air grips the ball, b (N·s/m). */
    public static final float WIND_B = 0.3f;
    /** The starting wind: a headwind blowing back toward the gun (m/s). */
    private static final Vector3f DEFAULT_WIND = new Vector3f(-6f, 0f, 0f);
    /** How much one key press changes the wind (m/s). */
    private static final float WIND_STEP = 2f;
    /** The strongest wind offered, either way (m/s). */
    private static final float MAX_WIND = 20f;
    /** Both balls' launch velocity (m/s; the tour's question flies it too: not modified). */
    public static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);

    // Step 1: the forces this demo shows, as fields so keys can change them.
    private final Wind wind = new Wind(DEFAULT_WIND, WIND_B);
    private final Vector3f windVelocity = new Vector3f(DEFAULT_WIND);

    /** Create the demo. */
    public WindDemo() {
        super("Wind (write your own demo)");
    }

    /**
     * Access the wind force.
     *
     * @return the live force (not null)
     */
    public Wind getWind() {
        return wind;
    }

    @Override
    protected void createScene() {
        // Step 2: the particles, each with an integrator holding the forces acting on it.
        addParticle("still air", ColorRGBA.Orange, Vector3f.ZERO, LAUNCH_VELOCITY, 1f,
                new ParticleIntegrator(new Gravity())).stopAtGround();
        addParticle("in the wind", new ColorRGBA(0.5f, 1f, 0.6f, 1f), Vector3f.ZERO,
                LAUNCH_VELOCITY, 1f, new ParticleIntegrator(new Gravity(), wind))
                .stopAtGround();
        // Step 3: the region the camera frames: x from -2 to 24 m, up to 7 m, 1 m grid.
        setView(-2f, 24f, 7f, 1f, 5, 0.35f);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        // Step 4: parameters. The panel (sliders, and the [ ] , . keys) and --set w=...
        // are generated from this declaration; the setter puts the value into the force.
        declareParameter(new DemoParameter("w", "wind along x",
                "m/s", -MAX_WIND, MAX_WIND, WIND_STEP, DEFAULT_WIND.x, 1,
                DemoParameter.Applies.LIVE, value -> {
                    windVelocity.x = value;
                    wind.setWindVelocity(windVelocity);
                }));
    }

    @Override
    protected void declareDraggables() {
        // Step 4b: what the mouse may drag (paused): the launch of both balls, the help and
        // the pages' mouse table are written from it.
        declareDraggable(Draggable.launchPosition("a ball", getParticles()));
        declareDraggable(Draggable.launchVelocity("a ball", getParticles()));
    }

    @Override
    protected void declareKeys() {
        // Step 5: keys. The help overlay (H) lists them automatically.
        bindKey(KeyInput.KEY_LEFT, "Left", "wind 2 m/s more toward the gun",
                () -> changeWind(-WIND_STEP));
        bindKey(KeyInput.KEY_RIGHT, "Right", "wind 2 m/s more toward the target",
                () -> changeWind(WIND_STEP));
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        // Step 6: HUD lines, every frame: append numbers with TextFormat (no garbage).
        text.append("Wind W = ");
        TextFormat.appendVector(text, windVelocity, 1).append(" m/s   (Left/Right change it)\n");
    }

    private void changeWind(float delta) {
        // Through the parameter, so the panel shows it too.
        getParameters().set("w", Math.max(-MAX_WIND, Math.min(MAX_WIND,
                windVelocity.x + delta)));
        // The equations at the top of the HUD show the new W.
        refreshEquations();
        restart();
    }

    /**
     * Step 7: the slide presentation mode shows (F8): the force with its W, and where each
     * ball lands.
     */
    @Override
    protected void writePresentation(Presentation slide) {
        TextFormat.appendFixed(slide.formula().append("a = g + (b/m)(W - V),   Wx = "),
                windVelocity.x, 1).append(" m/s");
        StringBuilder readout = slide.readout().append("lands at x:");
        List<DemoParticle> balls = getParticles();
        for (int i = 0; i < balls.size(); ++i) {
            DemoParticle ball = balls.get(i);
            readout.append(i == 0 ? "  " : ",  ").append(ball.getLabel()).append(' ');
            if (ball.hasLanded()) {
                TextFormat.appendFixed(readout, ball.getLandingX(), 2).append(" m");
            } else {
                readout.append("(in flight)");
            }
        }
    }
}
