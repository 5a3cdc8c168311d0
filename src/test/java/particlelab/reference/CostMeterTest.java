package particlelab.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;


/**
 * The meter's arithmetic on a scripted clock: no test times code. Each call of a workload
 * advances the fake clock by the time it is scripted to take, so every figure is exact.
 * With the tiny sweep (warm-up 5 ms, rounds of at least 2 ms, 3 rounds) and calls of 2 ms or
 * more, a warm-up is three calls and a round one call; calls of
 * {@link CostMeter#UNITS_PER_CLOCK_READ} units read the clock after every call.
 */
class CostMeterTest {

    private static final CostMeter.Budget TINY = CostMeter.Budget.TINY;
    private static final long MS = 1_000_000L;
    private static final int UNITS = CostMeter.UNITS_PER_CLOCK_READ;

    /** A clock that moves only when a scripted workload says. */
    private static final class FakeClock implements CostMeter.Clock {
        private long now;

        @Override
        public long nanos() {
            return now;
        }
    }

    /** A workload whose k-th call takes durations[k] ms (the last one after that). */
    private static CostMeter.Workload scripted(FakeClock clock, String name, List<String> log,
            long... durationsMs) {
        int[] call = {0};
        return units -> {
            int k = Math.min(call[0]++, durationsMs.length - 1);
            clock.now += durationsMs[k] * MS;
            log.add(name);
            return null;
        };
    }

    @Test
    void spreadIsMinMedianAndMaxWithTheMiddleTwoAveragedForAnEvenCount() {
        CostMeter.Spread odd = CostMeter.Spread.of(new double[] {3.0, 1.0, 2.0, 9.0, 4.0});
        assertEquals(1.0, odd.min(), 0.0);
        assertEquals(3.0, odd.median(), 0.0);
        assertEquals(9.0, odd.max(), 0.0);
        assertEquals(3.0, CostMeter.Spread.of(new double[] {4.0, 1.0, 2.0, 8.0}).median(), 0.0);
        assertThrows(IllegalArgumentException.class, () -> CostMeter.Spread.of(new double[0]));
    }

    @Test
    void spreadBeyondTheBoundGetsNoVerdict() {
        // max ÷ min of exactly the bound is still judged, a hair more is not
        assertFalse(new CostMeter.Spread(2.0, 2.5, 3.0).exceeds(1.5));
        assertTrue(new CostMeter.Spread(2.0, 2.5, 3.0001).exceeds(1.5));
        assertTrue(new CostMeter.Spread(0.0, 1.0, 1.0).exceeds(1.5), "a zero minimum");
        assertTrue(new CostMeter.Spread(Double.NaN, 1.0, 1.0).exceeds(1.5), "NaN");
    }

    @Test
    void sideBySideRotatesTheOrderAndTakesRatiosWithinEachRound() {
        FakeClock clock = new FakeClock();
        List<String> log = new ArrayList<>();
        // warm-up calls 2 ms; rounds: a 2, 4, 2 ms; b 4, 12, 8 ms, so b ÷ a is 2, 3, 4 by
        // round, while the ratio of the medians would be 8 / 2 = 4
        CostMeter.Workload a = scripted(clock, "a", log, 2, 2, 2, 2, 4, 2);
        CostMeter.Workload b = scripted(clock, "b", log, 2, 2, 2, 4, 12, 8);
        CostMeter.SideBySide timed = new CostMeter(TINY, clock).measureSideBySide(
                new CostMeter.Workload[] {a, b}, new int[] {UNITS, UNITS});
        // warm-up a, then b; round 0 starts with a, round 1 with b, round 2 with a
        assertEquals(List.of("a", "a", "a", "b", "b", "b", "a", "b", "b", "a", "a", "b"), log);
        CostMeter.Spread ratio = timed.ratio(1, 0);
        assertEquals(2.0, ratio.min(), 1e-12);
        assertEquals(3.0, ratio.median(), 1e-12);
        assertEquals(4.0, ratio.max(), 1e-12);
        assertEquals(0.25, timed.ratio(0, 1).min(), 1e-12);
        CostMeter.Spread slow = timed.nanosPerUnit(1);
        assertEquals(4.0 * MS / UNITS, slow.min(), 1e-9);
        assertEquals(8.0 * MS / UNITS, slow.median(), 1e-9);
        assertEquals(12.0 * MS / UNITS, slow.max(), 1e-9);
    }

    @Test
    void measureKeepsMinMedianAndMaxOfItsRounds() {
        FakeClock clock = new FakeClock();
        List<String> log = new ArrayList<>();
        CostMeter.Measurement measured = new CostMeter(TINY, clock).measure(
                scripted(clock, "w", log, 2, 2, 2, 3, 2, 5), UNITS);
        assertEquals(6, log.size(), "three warm-up calls and one a round");
        assertEquals(2.0 * MS / UNITS, measured.spread().min(), 1e-9);
        assertEquals(3.0 * MS / UNITS, measured.spread().median(), 1e-9);
        assertEquals(5.0 * MS / UNITS, measured.spread().max(), 1e-9);
        assertEquals(measured.spread().median(), measured.nanosPerUnit(), 0.0);
    }

    @Test
    void shortCallsShareOneClockReadAndLongOnesDoNot() {
        FakeClock clock = new FakeClock();
        List<String> log = new ArrayList<>();
        // calls of 1000 units taking 1 µs: the warm-up is 5000 calls (5 ms); each round times
        // its first call alone, then batches of UNITS_PER_CLOCK_READ / 1000 = 20 calls (20 µs,
        // less than a 32nd of the 2 ms round) until 2 ms: 1 + 100 · 20 calls
        CostMeter.Workload short1 = units -> {
            clock.now += 1000;
            log.add("s");
            return null;
        };
        new CostMeter(TINY, clock).measure(short1, 1000);
        assertEquals(5000 + 3 * (1 + 100 * 20), log.size());
        // calls of 1000 units taking 1 ms: the clock is read after every call, so a round of
        // 2 ms is two calls, not twenty
        log.clear();
        new CostMeter(TINY, clock).measure(scripted(clock, "l", log, 1), 1000);
        assertEquals(5 + 3 * 2, log.size());
    }

    @Test
    void sideBySideRefusesMismatchedUnits() {
        CostMeter meter = new CostMeter(TINY, new FakeClock());
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> meter.measureSideBySide(new CostMeter.Workload[] {units -> null},
                        new int[] {1, 2}));
        assertTrue(bad.getMessage().contains("got 1 and 2"), bad.getMessage());
    }
}
