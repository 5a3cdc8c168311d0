package particlelab.accuracy;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.aiming.Flight;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Stepper;


/**
 * Frame hitches: the canonical shot under linear drag, played at 60 frames per second with a
 * long frame injected after every {@value #FRAMES_BETWEEN_HITCHES} ordinary ones (a game that
 * keeps stalling), once with raw tpf (one step per frame) and once through the fixed-step clock
 * with its defaults (h = 1/60 s, frames clamped to 0.25 s, at most 16 steps a frame). The
 * landing point is compared with the exact range.
 */
final class HitchStudy {

    /** The long frames injected (in seconds); 0 is the run without hitches. */
    static final double[] HITCH_SECONDS = {0.0, 0.1, 0.5, 2.0};
    /** The drag rates b/m of the scenes (in 1/s). */
    static final double[] LINEAR_RATES = {0.5, 2.0};
    /** Ordinary frames between two hitches. */
    static final int FRAMES_BETWEEN_HITCHES = 30;
    /** The ordinary frame time (in seconds). */
    static final float FRAME_SECONDS = 1f / 60f;
    private static final int MAX_FRAMES = 100_000;

    /** One run. */
    static final class Run {
        final double linearRate;
        final SimulationClock.Mode mode;
        final double hitchSeconds;
        final double exactRange;
        final double landingX;
        final boolean finite;
        final boolean landed;
        final double droppedSeconds;
        final int steps;

        Run(double linearRate, SimulationClock.Mode mode, double hitchSeconds, double exactRange,
                double landingX, boolean finite, boolean landed, double droppedSeconds,
                int steps) {
            this.linearRate = linearRate;
            this.mode = mode;
            this.hitchSeconds = hitchSeconds;
            this.exactRange = exactRange;
            this.landingX = landingX;
            this.finite = finite;
            this.landed = landed;
            this.droppedSeconds = droppedSeconds;
            this.steps = steps;
        }

        double landingError() {
            return landingX - exactRange;
        }
    }

    /** Follows one shot step by step until it lands. */
    private static final class Shot implements SimulationClock.Stepper {
        private final Flight flight;
        private final Particle particle;
        private boolean landed;
        private double landingX = Double.NaN;
        private int steps;

        Shot(ForceModel forces) {
            flight = new Flight(new ParticleIntegrator(forces.toForces()));
            particle = new Particle(new Vector3f(), new Vector3f(20f, 30f, 0f), 1f);
        }

        @Override
        public void step(float stepSeconds) {
            if (landed) {
                return;
            }
            double fraction = flight.step(particle, stepSeconds);
            ++steps;
            if (fraction != Flight.NO_LANDING) {
                landed = true;
                landingX = flight.crossingX(fraction);
            }
        }
    }

    final List<Run> runs = new ArrayList<>();

    private HitchStudy() {
    }

    static HitchStudy run() {
        HitchStudy study = new HitchStudy();
        for (double k : LINEAR_RATES) {
            ForceModel forces = ForceModel.perUnitMass(CanonicalCase.G, k, 0.0, 0.0);
            MotionState launch = CanonicalCase.launch();
            double t = ClosedForms.landingTime(forces, launch);
            double range = ClosedForms.gravityLinearDrag(forces, launch, t, new MotionState())
                    .position[0];
            for (SimulationClock.Mode mode : SimulationClock.Mode.values()) {
                for (double hitch : HITCH_SECONDS) {
                    study.runs.add(fly(forces, k, mode, hitch, range));
                }
            }
        }
        return study;
    }

    private static Run fly(ForceModel forces, double k, SimulationClock.Mode mode, double hitch,
            double range) {
        SimulationClock clock = new SimulationClock();
        clock.setMode(mode);
        Shot flight = new Shot(forces);
        boolean finite = true;
        try {
            for (int frame = 0; frame < MAX_FRAMES && !flight.landed; ++frame) {
                boolean hitchFrame = hitch > 0.0
                        && frame % (FRAMES_BETWEEN_HITCHES + 1) == FRAMES_BETWEEN_HITCHES;
                clock.advance(hitchFrame ? (float) hitch : FRAME_SECONDS, flight);
            }
        } catch (NonFiniteStepException nonFinite) {
            finite = false;
        }
        finite = finite && flight.particle.isFinite();
        return new Run(k, mode, hitch, range, flight.landingX, finite, flight.landed,
                clock.getDroppedSeconds(), flight.steps);
    }
}
