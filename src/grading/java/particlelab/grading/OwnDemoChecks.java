package particlelab.grading;

import static particlelab.grading.Numbers.f;
import static particlelab.grading.Numbers.v;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.physics.Particle;

/**
 * Exercise 8's checks: the student's demo, stepped headless ({@code advancePhysics}, no jME
 * application), against the Euler step's closed forms.
 */
final class OwnDemoChecks {

    private static final float H = 1f / 60f;
    private static final float G = 9.8f;
    private static final int FRAMES = 30;
    /** The exercise's constants (its stub states them): W, b, launch, mass. */
    private static final float WIND_X = -6f;
    private static final float WIND_B = 0.3f;
    private static final Vector3f LAUNCH = new Vector3f(10f, 10f, 0f);

    private OwnDemoChecks() {
    }

    static Exercise exercise() {
        return new Exercise(8, "OwnDemo", DemoState.class, "Wind (your own demo)",
                List.of(new Check("scene", OwnDemoChecks::twoBallsAreLaunched),
                        new Check("still air", OwnDemoChecks::stillAirBallFallsUnderG),
                        new Check("wind", OwnDemoChecks::windBallFollowsTheDragSolution)));
    }

    private static void twoBallsAreLaunched(Submission s) throws Exception {
        DemoState demo = s.create(DemoState.class);
        int count = demo.getParticles().size();
        if (count != 2) {
            throw new Mistake("the demo has " + count + " particles; add two in createScene():"
                    + " \"still air\", then \"in the wind\"");
        }
        for (int i = 0; i < 2; ++i) {
            Particle ball = demo.getParticles().get(i).getParticle();
            if (!ball.velocity.equals(LAUNCH) || !ball.position.equals(Vector3f.ZERO)
                    || ball.getMass() != 1f) {
                throw new Mistake("ball " + (i + 1) + " starts at " + v(ball.position) + " with "
                        + v(ball.velocity) + ", mass " + f(ball.getMass())
                        + ": launch both from the origin at LAUNCH with MASS_KG");
            }
        }
    }

    /** Gravity only: {@code vy_n = vy0 − n·g·h}, {@code y_n = n·h·vy0 − g·h²·n(n+1)/2}. */
    private static void stillAirBallFallsUnderG(Submission s) throws Exception {
        Particle ball = run(s).getParticles().get(0).getParticle();
        double vy = LAUNCH.y - FRAMES * G * H;
        double y = FRAMES * H * LAUNCH.y - G * H * H * FRAMES * (FRAMES + 1) / 2.0;
        // 30 float steps at 10 m/s: rounding under 1e-4.
        if (!Numbers.near(vy, ball.velocity.y, 1e-4) || !Numbers.near(y, ball.position.y, 1e-4)
                || ball.velocity.x != LAUNCH.x) {
            throw new Mistake("after " + FRAMES + " frames the still-air ball is at "
                    + v(ball.position) + " with " + v(ball.velocity) + "; the Euler step under g"
                    + " alone gives y = " + f(y) + ", vy = " + f(vy));
        }
    }

    /** Wind is drag relative to the air: {@code V_n = V* + (V0 − V*)·rⁿ}, {@code V* = W + g/k}. */
    private static void windBallFollowsTheDragSolution(Submission s) throws Exception {
        Particle ball = run(s).getParticles().get(1).getParticle();
        double k = WIND_B;
        double decay = Math.pow(1.0 - k * H, FRAMES);
        double vx = WIND_X + (LAUNCH.x - WIND_X) * decay;
        double terminalY = -G / k;
        double vy = terminalY + (LAUNCH.y - terminalY) * decay;
        // 30 float steps, |V| under 33 m/s: rounding under 1e-4 m/s (as WindDemoTest).
        if (!Numbers.near(vx, ball.velocity.x, 1e-4) || !Numbers.near(vy, ball.velocity.y, 1e-4)) {
            throw new Mistake("after " + FRAMES + " frames the wind ball moves at "
                    + v(ball.velocity) + ", not (" + f(vx) + ", " + f(vy) + ", 0):"
                    + " the wind adds b (W - V) with W = WIND, b = WIND_B, and gravity acts too");
        }
    }

    private static DemoState run(Submission s) throws Exception {
        DemoState demo = s.create(DemoState.class);
        for (int frame = 0; frame < FRAMES; ++frame) {
            demo.getRun().advancePhysics(H);
        }
        return demo;
    }
}
