package particlelab.accuracy;

import java.util.Locale;
import particlelab.reference.CostMeter;


/**
 * The child JVM of the report's lecture-style row ({@link SpeedSpreads}): measures one
 * particle's lecture style against {@code step(Particle, h)} (linear drag) side by side, as
 * the report does in its own JVM, and prints two lines: {@value SpeedSpreads#PROBE_PREFIX},
 * the ratio's min, median and max over the rounds, and this JVM's collector; then
 * {@value SpeedSpreads#PROBE_AA_PREFIX} and the A/A pass's min, median and max
 * ({@code step(Particle, h)} over a second copy of itself, in the same rounds).
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
        CostMeter.SideBySide timed = SpeedSpreads.oneParticle(ForceMix.LINEAR, meter, true);
        CostMeter.Spread ratio = timed.ratio(SpeedSpreads.LECTURE_STYLE, SpeedSpreads.OBJECTS);
        CostMeter.Spread aa = timed.ratio(SpeedSpreads.OBJECTS_AGAIN, SpeedSpreads.OBJECTS);
        System.out.println(String.format(Locale.ROOT, "%s %.4f %.4f %.4f %s",
                SpeedSpreads.PROBE_PREFIX, ratio.min(), ratio.median(), ratio.max(),
                SpeedSpreads.thisCollector()));
        System.out.println(String.format(Locale.ROOT, "%s %.4f %.4f %.4f",
                SpeedSpreads.PROBE_AA_PREFIX, aa.min(), aa.median(), aa.max()));
    }
}
