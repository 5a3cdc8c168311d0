package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.VectorAssert;

/**
 * The clips as data: the committed clip files parse, a clip plays its keys with linear
 * interpolation, and a bad file is refused with its line and value named.
 */
class ClipReaderTest {

    private static final String TWO_TRACKS = "# a comment\n"
            + "0    rocket  0 0 0\n"
            + "\n"
            + "0    target  0 0 0\n"
            + "0.5  rocket  -1 2 0\n"
            + "0.25 target  1 0 0.5\n"
            + "1    rocket  -1 0 0\n";

    @ParameterizedTest
    @CsvSource({"clips/topple.clip, 7, 7", "clips/rebound.clip, 6, 3"})
    void theCommittedClipsParse(String resource, int rocketKeys, int targetKeys) {
        Clip clip = ClipReader.readResource(resource);
        assertEquals(resource.substring("clips/".length()), clip.getName());
        assertEquals(2, clip.countTracks());
        assertEquals(rocketKeys, clip.countKeys(clip.indexOf("rocket")));
        assertEquals(targetKeys, clip.countKeys(clip.indexOf("target")));
        for (int track = 0; track < 2; ++track) {
            // Every track starts where the body is at the contact.
            VectorAssert.assertVectorEquals(Vector3f.ZERO,
                    clip.copyOffset(track, 0.0, new Vector3f()), 0f);
        }
    }

    @Test
    void aClipPlaysItsKeysLinearlyAndHoldsTheLast() {
        Clip clip = ClipReader.parse("two.clip", TWO_TRACKS);
        int rocket = clip.indexOf("rocket");
        int target = clip.indexOf("target");
        assertEquals(-1, clip.indexOf("crate"));
        assertEquals(1f, clip.getDurationSeconds(), 0f);
        Vector3f offset = new Vector3f();
        // Halfway between keys 0 and 1, and between 1 and 2: exact in binary floats.
        VectorAssert.assertVectorEquals(new Vector3f(-0.5f, 1f, 0f),
                clip.copyOffset(rocket, 0.25, offset), 0f);
        VectorAssert.assertVectorEquals(new Vector3f(-1f, 1f, 0f),
                clip.copyOffset(rocket, 0.75, offset), 0f);
        VectorAssert.assertVectorEquals(new Vector3f(1f, 0f, 0.5f),
                clip.copyOffset(target, 3.0, offset), 0f);
        VectorAssert.assertVectorEquals(Vector3f.ZERO, clip.copyOffset(target, -1.0, offset), 0f);
        // The velocity the clip starts a body with: its first segment's slope.
        VectorAssert.assertVectorEquals(new Vector3f(-2f, 4f, 0f),
                clip.copyStartVelocity(rocket, offset), 0f);
        VectorAssert.assertVectorEquals(new Vector3f(4f, 0f, 2f),
                clip.copyStartVelocity(target, offset), 0f);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "0 rocket 0 0 0\\n0.5 rocket one 0 0"
                + " | line 2: x 'one' must be a number from -1000 to 1000 m",
        "0 rocket 0 0 0\\n0.5 rocket 1 0 | line 2: expected 5 fields (t track x y z), but found 4",
        "0 rocket 0 0 0\\n0.5 rocket 1 0 0\\n0.5 rocket 2 0 0"
                + " | line 3: time t = 0.5 s of track rocket must be later than its previous key",
        "# header\\n0.1 rocket 0 0 0 | line 2: track rocket must start at t = 0 with offset 0 0 0",
        "0 rocket 0 0 0\\nNaN rocket 1 0 0 | line 2: time t 'NaN' must be a number from 0 to 60 s",
        "0 Rocket 0 0 0 | line 1: track name 'Rocket' must be a lower-case letter",
        "0 rocket 0 0 0\\n0.5 rocket 1 0 0\\n0 target 0 0 0 | track target has 1 key",
        "# nothing but a comment | has no keys"})
    void aBadClipIsRefusedNamingTheLineAndTheValue(String text, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ClipReader.parse("bad.clip", text.replace("\\n", "\n")));
        assertTrue(e.getMessage().startsWith("clip bad.clip"), e.getMessage());
        assertTrue(e.getMessage().contains(expected.trim()), e.getMessage());
    }

    @Test
    void aMissingClipIsNamedWithWhereItShouldBe() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ClipReader.readResource("clips/none.clip"));
        assertEquals("clip clips/none.clip is not on the class path (expected in"
                + " assets/clips/none.clip)", e.getMessage());
    }
}
