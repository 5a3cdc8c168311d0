package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code demo --window WxH}: a size for screenshots at other resolutions, checked first. */
class DemoWindowOptionTest {

    @Test
    void aWindowSizeIsReadAsWidthByHeight() {
        assertArrayEquals(new int[] {1920, 1080}, DemoCommand.parseWindow("1920x1080"));
        assertArrayEquals(new int[] {640, 360}, DemoCommand.parseWindow("640x360"));
        // The smallest window the layout is made for (it hides HUD lines and says so).
        assertArrayEquals(new int[] {200, 150}, DemoCommand.parseWindow("200x150"));
        assertNull(DemoCommand.parseWindow(null));
    }

    @ParameterizedTest
    @ValueSource(strings = {"1920", "1920x", "x1080", "1920X1080", "-1x5", "199x480",
        "1024x149", "7681x1000", "1e3x768", "99999x99999", "1024x768x2", "10\u0007x20"})
    void aBadWindowSizeIsOneLineAndExitTwo(String value) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = DemoCommand.run(new String[] {"drag", "--window", value},
                new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        String message = err.toString(StandardCharsets.UTF_8);
        assertEquals(Program.USAGE, status);
        assertTrue(message.startsWith("particle-lab demo: --window: must be WIDTHxHEIGHT"),
                message);
        assertEquals(1, message.split("\n", -1).length - 1, message);
        assertTrue(message.chars().noneMatch(c -> c < 0x20 && c != '\n'), message);
        assertEquals("", out.toString(StandardCharsets.UTF_8));
    }
}
