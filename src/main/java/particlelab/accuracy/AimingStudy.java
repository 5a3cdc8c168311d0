package particlelab.accuracy;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * Aiming: the level shot of HelloAiming (S = 100 m, vx = 20 m/s) aimed by the lecture's formula
 * and by the discrete correction, flown by the shared integrator at a fixed h, and the miss
 * distance measured at the ground crossing, interpolated inside the last step. Swept against h
 * without drag, and against linear drag at h = 1/60 s (neither formula knows about drag).
 */
final class AimingStudy {

    /** Distance to the target (in metres), the HelloAiming default. */
    static final double DISTANCE = 100.0;
    /** Horizontal launch speed (in m/s), the HelloAiming default. */
    static final double VX = 20.0;
    /** The damping rates b/m of the drag sweep (in 1/s). */
    static final double[] DRAG_RATES = {0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5};
    /** The fixed step of the drag sweep (in seconds). */
    static final double DRAG_SWEEP_STEP = 1.0 / 60.0;
    private static final int MAX_STEPS = 10_000_000;

    /** One shot. */
    static final class Shot {
        final String sweep;
        final String formula;
        final double stepSeconds;
        final double linearRate;
        final double vy;
        final double missMetres;

        Shot(String sweep, String formula, double stepSeconds, double linearRate, double vy,
                double missMetres) {
            this.sweep = sweep;
            this.formula = formula;
            this.stepSeconds = stepSeconds;
            this.linearRate = linearRate;
            this.vy = vy;
            this.missMetres = missMetres;
        }
    }

    final List<Shot> shots = new ArrayList<>();

    private AimingStudy() {
    }

    static AimingStudy run(ReportConfig config) {
        AimingStudy study = new AimingStudy();
        double g = CanonicalCase.G;
        for (double h : config.steps()) {
            ForceModel forces = ForceModel.perUnitMass(g, 0.0, 0.0, 0.0);
            study.add("step", "lecture", h, 0.0, AimingFormulas.lectureVy(g, DISTANCE, VX), forces);
            study.add("step", "discrete", h, 0.0,
                    AimingFormulas.discreteVy(g, DISTANCE, VX, h), forces);
        }
        for (double k : DRAG_RATES) {
            ForceModel forces = ForceModel.perUnitMass(g, k, 0.0, 0.0);
            double h = DRAG_SWEEP_STEP;
            study.add("drag", "lecture", h, k, AimingFormulas.lectureVy(g, DISTANCE, VX), forces);
            study.add("drag", "discrete", h, k,
                    AimingFormulas.discreteVy(g, DISTANCE, VX, h), forces);
        }
        return study;
    }

    private void add(String sweep, String formula, double h, double k, double vy,
            ForceModel forces) {
        double landing = landingX(forces, VX, vy, h);
        shots.add(new Shot(sweep, formula, h, k, vy, landing - DISTANCE));
    }

    /**
     * Fly a shot from the origin with the shared integrator and find where it comes back to
     * y = 0, interpolating linearly inside the step that crosses.
     *
     * @return the landing x (in metres), NaN if it never lands
     */
    static double landingX(ForceModel forces, double vx, double vy, double stepSeconds) {
        ParticleIntegrator integrator = new ParticleIntegrator(forces.toForces());
        Particle particle = new Particle(new Vector3f(),
                new Vector3f((float) vx, (float) vy, 0f), (float) forces.getMassKg());
        float h = (float) stepSeconds;
        for (int n = 0; n < MAX_STEPS; ++n) {
            float x0 = particle.position.x;
            float y0 = particle.position.y;
            integrator.step(particle, h);
            float y1 = particle.position.y;
            if (y1 <= 0f && n > 0) {
                float x1 = particle.position.x;
                return x0 + (x1 - x0) * (double) y0 / ((double) y0 - y1);
            }
        }
        return Double.NaN;
    }
}
