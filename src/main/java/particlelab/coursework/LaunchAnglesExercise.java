package particlelab.coursework;

/** Exercise 4, the "Aim at any height" slide: both launch angles at a fixed speed. */
public interface LaunchAnglesExercise {

    /**
     * The two angles above the horizontal that send a shot of speed {@code s} through the point
     * {@code (x, y)} in a vacuum.
     *
     * @param speed the launch speed s (in m/s, &gt;0)
     * @param x the target's horizontal distance (in metres, &gt;0)
     * @param y the target's height above the launch (in metres)
     * @param gravity g (in m/s², &gt;0)
     * @param storeAngles storage for the low angle [0] and the high one [1] (in radians,
     *     modified only when reachable)
     * @return false when the target is out of reach
     */
    boolean angles(float speed, float x, float y, float gravity, float[] storeAngles);
}
