package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The Worms "CPU shot misprediction": the aimer predicts its shots with a step
 * {@code h_predict}, the game flies them with another, {@code h_fly}. The semi-implicit Euler
 * bullet lands {@code vx·h} short of the continuous parabola (see {@link LevelAim}), so a vy
 * that the predictor lands at S flies to about {@code S + vx·(h_predict − h_fly)}: long when
 * the predictor's step is the larger. With drag the Euler step also shortens the effective
 * launch by {@code h/2} times drag's deceleration, and the miss grows: measured 4 % above
 * {@code vx·|Δh|} with linear drag b/m = 0.1 /s and 26 % with quadratic drag c/m = 0.01 /m
 * (vx = 20 m/s, S = 50 m).
 */
public final class PredictorMismatch {

    private PredictorMismatch() {
    }

    /**
     * The drag-free estimate of the miss: {@code vx·(h_predict − h_fly)}.
     *
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @param predictStepSeconds h_predict (in seconds, finite, &gt;0)
     * @param flyStepSeconds h_fly (in seconds, finite, &gt;0)
     * @return the expected miss (in metres; positive: long)
     */
    public static double expectedMiss(double horizontalSpeed, double predictStepSeconds,
            double flyStepSeconds) {
        Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
        Validate.positive(predictStepSeconds, "predictor step h_predict (s)");
        Validate.positive(flyStepSeconds, "flight step h_fly (s)");
        return horizontalSpeed * (predictStepSeconds - flyStepSeconds);
    }

    /**
     * Fly the predicted shot with the game's own step: the shot the player sees.
     *
     * @param predicted the predictor's result, a hit (not null)
     * @param flight the simulator at h_fly, with the same forces and mass (not null)
     * @param toleranceMetres the tolerance the flown shot is judged by (in metres, finite,
     *     &gt;0)
     * @param storeShots where to append the flown shot (modified; may be null)
     * @return the flown shot: its landing, miss, and the predictor's shots plus this one (not
     *     null); no hit, with the reason, if it never came down
     */
    public static AimResult fly(AimResult predicted, ShotSimulator flight,
            double toleranceMetres, ShotLog storeShots) {
        Validate.notNull(predicted, "predicted");
        Validate.notNull(flight, "flight");
        Validate.positive(toleranceMetres, "tolerance (m)");
        float vx = (float) predicted.getHorizontalSpeed();
        float vy = (float) predicted.getVerticalSpeed();
        double distance = predicted.getTargetDistance();
        Landing landing = new Landing();
        boolean landed = flight.fire(vx, vy, landing);
        if (storeShots != null) {
            storeShots.record(vx, vy, landing, distance);
        }
        int shots = predicted.getShots() + 1;
        if (!landed) {
            return new AimResult(predicted.getMethod(), false, vx, vy, Double.NaN, Double.NaN,
                    distance, shots, "the shot with vy=" + vy + " m/s, flown at h="
                            + flight.getStepSeconds() + " s, did not come down in time");
        }
        double miss = landing.getX() - distance;
        boolean hit = Math.abs(miss) <= toleranceMetres;
        return new AimResult(predicted.getMethod(), hit, vx, vy, landing.getTimeSeconds(),
                landing.getX(), distance, shots, hit ? "hit" : "predicted at another step:"
                        + " missed by " + (float) miss + " m");
    }
}
