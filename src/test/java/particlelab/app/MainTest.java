package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class MainTest {

    /**
     * Every bad command line: exit 2, nothing on stdout, exactly one line on stderr naming
     * the option (or the bad word), and no exception text.
     *
     * @param named what the error line must name
     * @param commandLine the arguments, separated by spaces
     */
    @ParameterizedTest(name = "{1}")
    @CsvSource(delimiter = '|', value = {
        "--bogus         | trajectory --steps 3 --bogus 1",
        "--steps         | trajectory --steps",
        "--v0            | trajectory --v0 1,2 --steps 3",
        "--v0            | trajectory --v0 1,2,x --steps 3",
        "--g             | trajectory --g 0,NaN,0 --steps 3",
        "--mass          | trajectory --mass 0 --steps 3",
        "--mass          | trajectory --mass -1 --steps 3",
        "--mass          | trajectory --mass NaN --steps 3",
        "--linear-drag   | trajectory --linear-drag -0.1 --steps 3",
        "--quadratic-drag| trajectory --quadratic-drag -1 --steps 3",
        "--thrust        | trajectory --thrust -2 --steps 3",
        "--tpf           | trajectory --tpf 0 --steps 3",
        "--tpf           | trajectory --tpf -0.01 --steps 3",
        "--tpf           | trajectory --tpf NaN --steps 3",
        "--tpf           | trajectory --tpf Infinity --steps 3",
        "--duration      | trajectory --steps 3 --duration 1",
        "--until-ground  | trajectory --steps 3 --until-ground",
        "--until-ground  | trajectory --duration 2 --until-ground",
        "--steps         | trajectory",
        "--steps         | trajectory --steps -1",
        "--steps         | trajectory --steps 1.5",
        "--steps         | trajectory --steps 1000001",
        "--duration      | trajectory --duration 0",
        "--duration      | trajectory --duration 1e9",
        "--steps         | trajectory --steps 1 --steps 2",
        "stray           | trajectory stray --steps 1",
        "--distance      | aim --vx 20",
        "--vx            | aim --distance 100",
        "--distance      | aim --distance -5 --vx 20",
        "--vx            | aim --distance 100 --vx 0",
        "--g             | aim --distance 100 --vx 20 --g 0",
        "--g             | aim --distance 100 --vx 20 --g -9.8",
        "--mass          | aim --distance 100 --vx 20 --mass=-1",
        "--linear-drag   | aim --distance 100 --vx 20 --linear-drag -1",
        "--quadratic-drag| aim --distance 100 --vx 20 --quadratic-drag NaN",
        "--tpf           | aim --distance 100 --vx 20 --tpf 0",
        "--method        | aim --distance 100 --vx 20 --method magic",
        "--tolerance     | aim --distance 100 --vx 20 --method iterative --tolerance 0",
        "--tolerance     | aim --distance 100 --vx 20 --tolerance 0.01",
        "--distance      | aim --distance 250 --vx 20 --linear-drag 0.1",
        "--csv           | aim --distance 100 --vx 20 --csv=yes",
        "--vx            | aim --distance 100 --vx --csv",
        "fly             | fly --far",
    })
    void badCommandLineIsOneLineNamingTheProblemAndExitTwo(String named, String commandLine) {
        CommandRun run = CommandRun.of(commandLine.trim().split(" +"));
        assertEquals(2, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(named.trim()), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertTrue(run.err.startsWith("particle-lab"), run.toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"--help", "-h", "help"})
    void helpListsEverySubcommandAndWhereToReadMore(String help) {
        CommandRun run = CommandRun.of(help);
        assertEquals(0, run.code);
        assertEquals("", run.err);
        for (Command command : Commands.all()) {
            // The summary is wrapped: compare words only.
            String words = run.out.replaceAll("\\s+", " ");
            assertTrue(words.contains(" " + command.name() + " " + command.summary() + " "),
                    command.name() + " and its summary in\n" + run.out);
            assertTrue(run.out.contains("\n  " + command.name() + " "),
                    command.name() + " in\n" + run.out);
        }
        assertTrue(run.out.contains("\n  help "));
        assertTrue(run.out.contains("particle-lab demo --help"));
        assertTrue(run.out.contains("particle-lab report --help"));
        assertFitsEightyColumns(run.out);
    }

    @Test
    void anUnknownCommandIsRefusedNamingEveryCommand() {
        CommandRun run = CommandRun.of("fly", "--far");
        assertEquals(2, run.code);
        for (Command command : Commands.all()) {
            assertTrue(run.err.contains(command.name() + ", "), command.name() + " in " + run);
        }
        assertTrue(run.err.contains(", help "), run.toString());
    }

    /**
     * Every declared command: its --help is its declared options' help, and a bad option is
     * refused in one line naming it, before the command does anything (the demo opens no
     * window, the report writes nothing).
     */
    @Test
    void everyDeclaredCommandHasHelpAndRefusesABadOption() {
        assertEquals(10, Commands.all().size(), "the launcher's commands");
        for (Command command : Commands.all()) {
            CommandRun help = CommandRun.of(command.name(), "--help");
            assertEquals(0, help.code, command.name() + ": " + help);
            assertEquals("", help.err, command.name() + ": " + help);
            assertEquals(command.options().get().help(), help.out, command.name());
            assertTrue(help.out.startsWith("Usage: particle-lab " + command.name()),
                    command.name() + ": " + help);
            assertEquals(help.out, CommandRun.of("help", command.name()).out, command.name());

            CommandRun bad = CommandRun.of(command.name(), "--no-such-option", "1");
            assertEquals(2, bad.code, command.name() + ": " + bad);
            assertEquals("", bad.out, command.name() + ": " + bad);
            assertEquals(1, bad.errLines().size(), command.name() + ": " + bad);
            assertTrue(bad.err.contains("--no-such-option"), command.name() + ": " + bad);
            assertFalse(bad.err.contains("Exception"), command.name() + ": " + bad);
        }
    }

    /**
     * A command class that is not in {@link Commands} cannot be run: every
     * {@code app/*Command.java} with a {@code NAME} must be listed (a plain source scan).
     *
     * @throws IOException if the sources cannot be read
     */
    @Test
    void everyCommandClassIsRegistered() throws IOException {
        Path app = Paths.get("src", "main", "java", "particlelab", "app");
        int classes = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(app, "*Command.java")) {
            for (Path file : files) {
                String source = Files.readString(file);
                Matcher name = Pattern.compile(
                        "public static final String NAME = \"([a-z]+)\";").matcher(source);
                if (name.find()) {
                    ++classes;
                    assertNotNull(Commands.find(name.group(1)),
                            file.getFileName() + " declares " + name.group(1)
                                    + " but Commands does not list it");
                }
            }
        }
        assertEquals(Commands.all().size(), classes, "command classes with a NAME");
    }

    @Test
    void commandHelpListsEveryOptionWithItsDefault() {
        checkCommandHelp("trajectory", TrajectoryCommand.options());
        checkCommandHelp("aim", AimCommand.options());
        // Words only: the help wraps lines.
        String trajectory = CommandRun.of("trajectory", "--help").out.replaceAll("\\s+", " ");
        for (String fact : new String[] {"Default 0,0,0", "Default 10,10,0", "Default 1.",
                "Default 0,-9.8,0", "Default 1/60", "(m/s^2)", "(kg, > 0)"}) {
            assertTrue(trajectory.contains(fact), fact + " in\n" + trajectory);
        }
        String aim = CommandRun.of("aim", "-h").out;
        String aimWords = aim.replaceAll("\\s+", " ");
        for (String fact : new String[] {"Default 9.8", "Default lecture", "Default 0.001",
                "method,vx,vy,flight_time,landing_x,miss,shots"}) {
            assertTrue(aimWords.contains(fact), fact + " in\n" + aim);
        }
        assertEquals(aim, CommandRun.of("help", "aim").out);
    }

    @Test
    void helpWinsOverOtherwiseBadArguments() {
        CommandRun run = CommandRun.of("aim", "--bogus", "--help");
        assertEquals(0, run.code);
        assertTrue(run.out.startsWith("Usage: particle-lab aim [OPTIONS]"));
    }

    private static void checkCommandHelp(String command, Options declared) {
        CommandRun run = CommandRun.of(command, "--help");
        assertEquals(0, run.code);
        assertEquals("", run.err);
        for (String option : declared.names()) {
            assertTrue(run.out.contains("\n  " + option + " ")
                    || run.out.contains("\n  " + option + "\n"), option + " in\n" + run.out);
        }
        assertTrue(run.out.contains("--help"));
        assertFitsEightyColumns(run.out);
    }

    private static void assertFitsEightyColumns(String text) {
        for (String line : text.split("\\R")) {
            assertTrue(line.length() <= 80, "fits 80 columns: " + line);
        }
    }
}
