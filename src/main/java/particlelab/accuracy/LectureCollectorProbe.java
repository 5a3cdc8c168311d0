package particlelab.accuracy;

import java.util.Locale;
import particlelab.reference.CostMeter;


/**
 * The child JVM of the report's lecture-style row ({@link SpeedSpreads}): measures one
 * particle's lecture style against {@code step(Particle, h)} (linear drag) side by side, as
 * the report does in its own JVM, and prints one line: {@value SpeedSpreads#PROBE_PREFIX},
 * the ratio's min, median and max over the rounds, and this JVM's collector.
 */
public final class LectureCollectorProbe {

    private LectureCollectorProbe() {
    }

    /**
     * Measure and print.
     *
     * @param args the report's size ({@code FULL}, {@code QUICK} or {@code TINY})
     */
    public static void main(String[] args) {
        ReportConfig.Size size;
        try {
            size = ReportConfig.Size.valueOf(args.length == 1 ? args[0] : "");
        } catch (IllegalArgumentException bad) {
            System.err.println("usage: LectureCollectorProbe FULL|QUICK|TINY (got "
                    + String.join(" ", args) + ")");
            System.exit(2);
            return;
        }
        CostMeter meter = new CostMeter(ReportConfig.of(size).budget());
        CostMeter.Spread ratio = SpeedSpreads.oneParticle(ForceMix.LINEAR, meter, true)
                .ratio(2, 1);
        System.out.println(String.format(Locale.ROOT, "%s %.4f %.4f %.4f %s",
                SpeedSpreads.PROBE_PREFIX, ratio.min(), ratio.median(), ratio.max(),
                SpeedSpreads.thisCollector()));
    }
}
