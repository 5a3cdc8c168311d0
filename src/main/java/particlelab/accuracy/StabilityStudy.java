package particlelab.accuracy;

import java.util.ArrayList;
import java.util.List;
import particlelab.physics.ParticleIntegrator;
import particlelab.reference.Scheme;


/**
 * The stability map: the largest stable step of every stepper at each damping rate b/m,
 * measured by {@link StabilityMap} and set beside theory; and of the shared integrator on a
 * spring of stiffness {@link StabilityMap#SPRING_STIFFNESS} damped at each of those rates,
 * beside the damped oscillator's limit {@link ParticleIntegrator#stableStepLimit}.
 */
final class StabilityStudy {

    /** One measured limit. */
    static final class Limit {
        final Scheme scheme;
        final double linearRate;
        final double measuredSeconds;
        final double theorySeconds;

        Limit(Scheme scheme, double linearRate, double measuredSeconds, double theorySeconds) {
            this.scheme = scheme;
            this.linearRate = linearRate;
            this.measuredSeconds = measuredSeconds;
            this.theorySeconds = theorySeconds;
        }
    }

    final List<Limit> limits = new ArrayList<>();
    /** The spring series: the shared integrator, λ = b/m, ω² = SPRING_STIFFNESS. */
    final List<Limit> springLimits = new ArrayList<>();

    private StabilityStudy() {
    }

    static int units(ReportConfig config) {
        return (Scheme.values().length + 1) * config.linearRates().length;
    }

    static StabilityStudy run(ReportConfig config, ProgressBar progress) {
        StabilityStudy study = new StabilityStudy();
        for (Scheme scheme : Scheme.values()) {
            progress.phase("stability map: " + scheme.id());
            for (double rate : config.linearRates()) {
                double measured = StabilityMap.maxStableStep(scheme, rate, CanonicalCase.G);
                study.limits.add(new Limit(scheme, rate, measured, scheme.theoryStableStep(rate)));
                progress.advance();
            }
        }
        progress.phase("stability map: semi-implicit Euler with a spring");
        for (double rate : config.linearRates()) {
            double measured = StabilityMap.maxStableStepSpring(rate, StabilityMap.SPRING_STIFFNESS);
            study.springLimits.add(new Limit(Scheme.SEMI_IMPLICIT_EULER, rate, measured,
                    ParticleIntegrator.stableStepLimit(rate, StabilityMap.SPRING_STIFFNESS)));
            progress.advance();
        }
        return study;
    }
}
