package particlelab.accuracy;

import java.util.ArrayList;
import java.util.List;
import particlelab.aiming.IterativeAim;
import particlelab.aiming.Landing;
import particlelab.aiming.LevelAim;
import particlelab.aiming.ShotSimulator;
import particlelab.physics.ParticleIntegrator;
import particlelab.reference.ForceModel;


/**
 * Aiming: the level shot of HelloAiming (S = 100 m, vx = 20 m/s) aimed three ways — the
 * lecture's formula, the discrete correction (both from {@link LevelAim}) and iterative
 * shoot-and-adjust ({@link IterativeAim}) — each flown by the shared integrator at a fixed h
 * through a {@link ShotSimulator}, its miss read at the ground crossing interpolated inside the
 * last step. Swept against h without drag, and against linear drag at h = 1/60 s (the closed
 * forms know nothing of drag; iterative aiming does, until the target is out of reach).
 */
final class AimingStudy {

    /** Distance to the target (in metres), the HelloAiming default. */
    /** Sweep name (in aiming.csv): h varies, no drag. */
    static final String STEP_SWEEP = "step";
    /** Sweep name (in aiming.csv): drag varies at {@link #DRAG_SWEEP_STEP}. */
    static final String DRAG_SWEEP = "drag";
    /** Formula name (in aiming.csv): the lecture's vy = g·S/(2·vx). */
    static final String LECTURE = "lecture";
    /** Formula name (in aiming.csv): the discrete correction vy = g·S/(2·vx) + g·h/2. */
    static final String DISCRETE = "discrete";
    /** Formula name (in aiming.csv): shoot and adjust. */
    static final String ITERATIVE = "iterative";
    static final double DISTANCE = 100.0;
    /** Horizontal launch speed (in m/s), the HelloAiming default. */
    static final double VX = 20.0;
    /** The damping rates b/m of the drag sweep (in 1/s). */
    static final double[] DRAG_RATES = {0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5};
    /** The fixed step of the drag sweep (in seconds). */
    static final double DRAG_SWEEP_STEP = 1.0 / 60.0;
    /** How close iterative aiming must land (in metres). */
    static final double TOLERANCE = 1e-3;
    /** The most shots iterative aiming may fire. */
    static final int MAX_SHOTS = 100;
    /** A shot still in the air after this long never lands (in seconds). */
    private static final float MAX_FLIGHT_SECONDS = 3600f;

    /** One aimed shot. */
    static final class Shot {
        final String sweep;
        final String formula;
        final double stepSeconds;
        final double linearRate;
        final double vy;
        /** landing x − S (in metres); NaN when the target was out of reach. */
        final double missMetres;
        final int shots;

        Shot(String sweep, String formula, double stepSeconds, double linearRate, double vy,
                double missMetres, int shots) {
            this.sweep = sweep;
            this.formula = formula;
            this.stepSeconds = stepSeconds;
            this.linearRate = linearRate;
            this.vy = vy;
            this.missMetres = missMetres;
            this.shots = shots;
        }
    }

    final List<Shot> shots = new ArrayList<>();
    private final Landing landing = new Landing();

    private AimingStudy() {
    }

    static AimingStudy run(ReportConfig config) {
        AimingStudy study = new AimingStudy();
        for (double h : config.steps()) {
            study.aimAllWays(STEP_SWEEP, h, 0.0);
        }
        for (double k : DRAG_RATES) {
            study.aimAllWays(DRAG_SWEEP, DRAG_SWEEP_STEP, k);
        }
        return study;
    }

    private void aimAllWays(String sweep, double h, double k) {
        double g = CanonicalCase.G;
        ForceModel forces = ForceModel.perUnitMass(g, k, 0.0, 0.0);
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(forces.toForces()),
                (float) forces.getMassKg(), (float) h, MAX_FLIGHT_SECONDS);
        fire(simulator, sweep, LECTURE, h, k, LevelAim.lectureVy(g, DISTANCE, VX));
        fire(simulator, sweep, DISCRETE, h, k, LevelAim.discreteVy(g, DISTANCE, VX, h));
        IterativeAim aimer = new IterativeAim(simulator, g, TOLERANCE, MAX_SHOTS);
        particlelab.aiming.AimResult result = aimer.aim(DISTANCE, VX);
        double miss = result.isHit() ? result.getMiss() : Double.NaN;
        shots.add(new Shot(sweep, ITERATIVE, h, k, result.getVerticalSpeed(), miss,
                result.getShots()));
    }

    private void fire(ShotSimulator simulator, String sweep, String formula, double h,
            double k, double vy) {
        boolean landed = simulator.fire((float) VX, (float) vy, landing);
        double miss = landed ? landing.getX() - DISTANCE : Double.NaN;
        shots.add(new Shot(sweep, formula, h, k, vy, miss, 1));
    }
}
