package particlelab.accuracy;

import java.util.ArrayList;
import java.util.List;

/**
 * The stability map: the largest stable step of every stepper at each damping rate b/m,
 * measured by {@link StabilityMap} and set beside theory.
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

    private StabilityStudy() {
    }

    static int units(ReportConfig config) {
        return Scheme.values().length * config.linearRates().length;
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
        return study;
    }
}
