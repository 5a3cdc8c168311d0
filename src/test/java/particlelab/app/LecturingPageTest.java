package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code docs/lecturing.md} follows the tour's list ({@link LectureTour}) so it cannot drift:
 * one section per stop, in order, headed by the stop's number and slide, naming the command
 * that opens the stop's demo in its state and the tour stop, with something to say and a
 * question for the room. Its {@code tour --list} transcript is run by {@link TranscriptTest}.
 */
class LecturingPageTest {

    private static final String PAGE = "docs/lecturing.md";
    private static final String HEADING = "### ";

    @Test
    void theSectionsAreTheTourStopsInOrder() throws IOException {
        List<String> lines = Files.readAllLines(Paths.get(PAGE));
        List<Integer> headings = new ArrayList<>();
        for (int i = 0; i < lines.size(); ++i) {
            if (lines.get(i).startsWith(HEADING)) {
                headings.add(i);
            }
        }
        List<LectureTour.Stop> stops = LectureTour.stops();
        assertEquals(stops.size(), headings.size(), PAGE + ": one section per tour stop");
        for (int s = 0; s < stops.size(); ++s) {
            LectureTour.Stop stop = stops.get(s);
            int number = s + 1;
            int start = headings.get(s);
            int end = s + 1 < headings.size() ? headings.get(s + 1) : lines.size();
            assertEquals(HEADING + number + ". " + stop.getSlide(), lines.get(start),
                    PAGE + ":" + (start + 1));
            String section = String.join(" ", lines.subList(start, end));
            StringBuilder command = new StringBuilder("`particle-lab demo ")
                    .append(stop.getDemo());
            for (String setting : stop.getSettings()) {
                command.append(" --set ").append(setting);
            }
            command.append('`');
            assertTrue(section.contains(command), PAGE + ", stop " + number + ": " + command);
            assertTrue(section.contains("`particle-lab tour --stop " + number + "`"),
                    PAGE + ", stop " + number + ": the tour command");
            assertTrue(section.contains("What to say: "), PAGE + ", stop " + number);
            assertTrue(section.contains("Ask the room:") && section.contains("?"),
                    PAGE + ", stop " + number + ": a question for the room");
        }
    }

    @Test
    void thePageShowsTheTourListTranscript() throws IOException {
        String page = Files.readString(Paths.get(PAGE));
        assertTrue(page.contains("```\n$ particle-lab tour --list\n1   "), PAGE);
    }
}
