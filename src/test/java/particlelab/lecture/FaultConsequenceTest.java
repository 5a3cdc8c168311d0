package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParameters;
import particlelab.physics.SimulationClock;

/**
 * A bug hunt's consequence ({@link FaultConsequence}): the landings flown ahead once per
 * change, the phrase the HUD's fault line ends with, and one copy of it for the demos that
 * fly a fault ahead (pull, drag, thrust), not one per demo.
 */
class FaultConsequenceTest {

    private static final Path LECTURE = Paths.get("src/main/java/particlelab/lecture");

    /** A flight that lands at fixed places and counts its flights. */
    private static final class CountingFlight implements FaultConsequence.AheadFlight {
        private final double faulty;
        private final double correct;
        private int flights;

        CountingFlight(double faulty, double correct) {
            this.faulty = faulty;
            this.correct = correct;
        }

        @Override
        public double landingX(int fault, float stepSeconds) {
            ++flights;
            return fault == 0 ? correct : faulty;
        }
    }

    /** @return a bug hunt of one fault, switched on as {@code --set fault=a} does */
    private static FaultHunt oneFault() {
        FaultHunt faults = new FaultHunt(new String[] {"a"}, new String[] {"fault a"},
                new String[] {"a"});
        DemoParameters parameters = new DemoParameters();
        parameters.add(faults.switchParameter(() -> { }));
        parameters.set(FaultHunt.PARAMETER, 1f);
        parameters.start();
        return faults;
    }

    @Test
    void fliesOnlyWhenTheDemoSaysSomethingChangedOrHChanged() {
        SimulationClock clock = new SimulationClock();
        FaultConsequence consequence = new FaultConsequence(oneFault(), clock, "the ball",
                "the correct code");
        CountingFlight flight = new CountingFlight(12.5, 10.0);
        consequence.setFlight(flight);
        assertEquals(12.5, consequence.getFaultyLandingX());
        assertEquals(10.0, consequence.getCorrectLandingX());
        StringBuilder hud = new StringBuilder();
        consequence.appendHudLine(hud, "B");
        // one flight with the fault and one with the correct code, not three pairs
        assertEquals(2, flight.flights);
        consequence.markStale();
        consequence.getFaultyLandingX();
        assertEquals(4, flight.flights);
        clock.setStepSeconds(1f / 30f);
        consequence.getCorrectLandingX();
        assertEquals(6, flight.flights);
    }

    @Test
    void thePhraseSaysHowFarShortOrBeyondTheCorrectLandingOrThatItNeverLands() {
        SimulationClock clock = new SimulationClock();
        FaultConsequence consequence = new FaultConsequence(oneFault(), clock, "the ball",
                "the correct code");
        consequence.setFlight(new CountingFlight(12.5, 10.0));
        StringBuilder hud = new StringBuilder();
        consequence.appendHudLine(hud, "B");
        assertEquals("FAULT on: fault a (fault=a): lands at x = 12.50 m, 2.50 m beyond the"
                + " correct code's 10.00 m\n", hud.toString());
        consequence.setFlight(new CountingFlight(7.25, 10.0));
        hud.setLength(0);
        consequence.appendHudLine(hud, "B");
        assertEquals("FAULT on: fault a (fault=a): lands at x = 7.25 m, 2.75 m short of the"
                + " correct code's 10.00 m\n", hud.toString());
        consequence.setFlight(new CountingFlight(Double.NaN, 10.0));
        hud.setLength(0);
        consequence.appendHudLine(hud, "B");
        assertEquals("FAULT on: fault a (fault=a): the ball never lands (the correct code"
                + " lands at x = 10.00 m)\n", hud.toString());
    }

    @Test
    void withoutAFaultNothingIsFlownAndTheLandingsAreNaN() {
        FaultHunt none = new FaultHunt(new String[] {"a"}, new String[] {"fault a"},
                new String[] {"a"});
        FaultConsequence consequence = new FaultConsequence(none, new SimulationClock(),
                "the ball", "the correct code");
        CountingFlight flight = new CountingFlight(12.5, 10.0);
        consequence.setFlight(flight);
        assertTrue(Double.isNaN(consequence.getFaultyLandingX()));
        assertTrue(Double.isNaN(consequence.getCorrectLandingX()));
        assertEquals(0, flight.flights);
    }

    @Test
    void theConsequenceIsWrittenAndRefreshedInOneClassNotInEachDemo() throws IOException {
        // The review found the landing accessors, their refresh and the phrase three times
        // (pull, drag, thrust); a demo now gives its flight and nothing else.
        List<String> copies = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(LECTURE, "*.java")) {
            for (Path file : files) {
                String source = new String(Files.readAllBytes(file), "UTF-8");
                boolean theClass = source.contains("final class FaultConsequence");
                if (!theClass && (source.contains("getFaultyLandingX()")
                        || source.contains("consequenceStale")
                        || source.contains("MAX_FLIGHT_STEPS = "))) {
                    copies.add(file.getFileName().toString());
                }
            }
        }
        assertEquals(List.of(), copies);
    }
}
