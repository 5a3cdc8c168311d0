package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The shipped font, read as jME reads it, has a glyph for every character it promises. */
class HudFontTest {

    @Test
    void shippedFontHasEveryPromisedCharacterAndTheSignsTheHudNeeds() throws IOException {
        Set<Integer> ids = new HashSet<>();
        String page = null;
        try (InputStream in = HudFontTest.class.getClassLoader()
                .getResourceAsStream(HudFont.ASSET)) {
            assertNotNull(in, HudFont.ASSET + " is not on the classpath");
            BufferedReader reader = new BufferedReader(
                    new InputStreamReader(in, StandardCharsets.US_ASCII));
            for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                String[] tokens = line.split("[\\s=]+");
                if (tokens[0].equals("char")) {
                    ids.add(Integer.parseInt(tokens[2]));
                } else if (tokens[0].equals("page")) {
                    page = tokens[4].replace("\"", "");
                }
            }
        }
        StringBuilder missing = new StringBuilder();
        for (int i = 0; i < HudFont.CHARACTERS.length(); ++i) {
            if (!ids.contains((int) HudFont.CHARACTERS.charAt(i))) {
                missing.append(HudFont.CHARACTERS.charAt(i));
            }
        }
        // The signs jME's Default.fnt lacks, which the HUD prints.
        for (char c : "²·λ−≈→×".toCharArray()) {
            if (!ids.contains((int) c)) {
                missing.append(c);
            }
        }
        assertEquals("", missing.toString());
        assertEquals(HudFont.BASE_NAME + ".png", page);
        assertNotNull(HudFontTest.class.getClassLoader().getResource("Fonts/" + page));
    }
}
