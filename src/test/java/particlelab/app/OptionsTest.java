package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

class OptionsTest {

    private static Options declare() {
        return new Options("particle-lab test", "A command for tests.")
                .value("--mass", "KG", "the mass (in kg); default 1")
                .value("--v0", "X,Y,Z", "the launch velocity (in m/s)")
                .value("--steps", "N", "the number of steps")
                .value("--method", "NAME", "lecture or iterative")
                .value("--name", "TEXT", "a required name")
                .flag("--csv", "print CSV")
                .flag("--until-ground", "stop at the ground");
    }

    private static Options parse(String... args) {
        Options options = declare();
        options.parse(args);
        return options;
    }

    private static String error(Runnable action) {
        UsageException e = assertThrows(UsageException.class, action::run);
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void readsSpaceAndEqualsFormsFlagsVectorsAndFractions() {
        Options options = parse("--mass", "2.5", "--v0=10,-10,0", "--csv", "--steps=7");
        assertEquals(2.5f, options.positiveFloat("--mass", 1f));
        assertEquals(new Vector3f(10f, -10f, 0f), options.vector("--v0", Vector3f.ZERO));
        assertTrue(options.has("--csv"));
        assertFalse(options.has("--until-ground"));
        assertEquals(7, options.intInRange("--steps", 0, 0, 10));
        assertEquals(1f / 60f, parse("--mass", "1/60").positiveFloat("--mass", 1f));
    }

    @Test
    void absentOptionsGiveTheirDefaultsAndDefaultVectorsAreCopies() {
        Options options = parse();
        assertEquals(1f, options.positiveFloat("--mass", 1f));
        Vector3f fallback = new Vector3f(1f, 2f, 3f);
        Vector3f read = options.vector("--v0", fallback);
        read.x = 9f;
        assertEquals(1f, fallback.x);
        assertEquals("lecture", options.choice("--method", "lecture", "lecture", "iterative"));
    }

    @Test
    void negativeValuesAreValuesButDoubleDashTokensAreNot() {
        assertEquals(new Vector3f(0f, -9.8f, 0f),
                parse("--v0", "0,-9.8,0").vector("--v0", Vector3f.ZERO));
        assertEquals(-3f, parse("--mass", "-3").finiteFloat("--mass", 0f));
        assertEquals("--mass: needs a value KG, but none was given"
                + " (see particle-lab test --help)", error(() -> parse("--mass", "--csv")));
    }

    @Test
    void badValuesNameTheOptionTheRuleAndTheValue() {
        assertEquals("--mass: must be a finite number > 0, but was -1",
                error(() -> parse("--mass", "-1").positiveFloat("--mass", 1f)));
        assertEquals("--mass: must be a finite number > 0, but was NaN",
                error(() -> parse("--mass", "NaN").positiveFloat("--mass", 1f)));
        assertEquals("--mass: must be a finite number >= 0, but was 1e60",
                error(() -> parse("--mass", "1e60").nonNegativeFloat("--mass", 1f)));
        assertEquals("--v0: must be three finite numbers X,Y,Z such as 0,-9.8,0, but was 1,2",
                error(() -> parse("--v0", "1,2").vector("--v0", Vector3f.ZERO)));
        assertEquals("--steps: must be a whole number from 0 to 10, but was 2.5",
                error(() -> parse("--steps", "2.5").intInRange("--steps", 0, 0, 10)));
        assertEquals("--steps: must be a whole number from 0 to 10, but was 99999999999999999999",
                error(() -> parse("--steps", "99999999999999999999")
                        .intInRange("--steps", 0, 0, 10)));
        assertEquals("--method: must be one of lecture, iterative, but was magic",
                error(() -> parse("--method", "magic")
                        .choice("--method", "lecture", "lecture", "iterative")));
    }

    @Test
    void badCommandLinesAreOneLineErrors() {
        assertTrue(error(() -> parse("--bogus", "1")).startsWith("--bogus: unknown option"));
        assertTrue(error(() -> parse("stray")).startsWith("unexpected argument stray"));
        assertEquals("--csv: is a flag and takes no value, but was given yes",
                error(() -> parse("--csv=yes")));
        assertTrue(error(() -> parse("--mass", "1", "--mass", "2"))
                .startsWith("--mass: given twice"));
        assertTrue(error(() -> parse("--mass=")).startsWith("--mass: needs a value KG"));
        assertTrue(error(() -> parse().string("--name")).startsWith("--name: is required"));
        assertTrue(error(() -> parse("--v0", "1,x\n,3").vector("--v0", Vector3f.ZERO))
                .endsWith("but was 1,x\\u000a,3"));
    }

    @Test
    void exactlyOneOfRejectsNoneAndTwo() {
        assertTrue(error(() -> parse().exactlyOneOf("--steps", "--until-ground"))
                .startsWith("--steps: missing; give exactly one of --steps, --until-ground"));
        assertEquals("--steps: cannot be combined with --until-ground; give at most one of "
                + "--steps, --until-ground", error(() -> parse("--steps", "3", "--until-ground")
                        .exactlyOneOf("--steps", "--until-ground")));
        parse("--until-ground").exactlyOneOf("--steps", "--until-ground");
    }

    @Test
    void helpSkipsValidationAndListsEveryOption() {
        Options options = parse("--bogus", "-h");
        assertTrue(options.isHelpRequested());
        String help = options.help();
        for (String name : options.names()) {
            assertTrue(help.contains(name), name + " in\n" + help);
        }
        assertTrue(help.contains("--help"));
        for (String line : help.split("\n")) {
            assertTrue(line.length() <= 79, "fits 80 columns: " + line);
        }
    }
}
