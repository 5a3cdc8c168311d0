package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The line confirming a screenshot names the whole path, however long (it was cut at 40). */
class ScreenshotLineTest {

    @Test
    void theConfirmationGivesTheWholePath() {
        String path = "/tmp/particle-lab/lecture-pictures/helloaiming-at-vx-21-and-h-1-60.png";
        assertEquals("screenshot " + path + ": 1280x720 pixels",
                DemoCommand.writtenLine(path, "1280x720 pixels"));
        // Control characters stay visible, as in every message naming a user's text.
        assertEquals("screenshot a\\u000ab.png: s", DemoCommand.writtenLine("a\nb.png", "s"));
    }
}
