package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A sweep of hostile command lines over every command: extreme and malformed numbers, steps
 * that overflow or cannot move, masses at the edge of the float range. Each must be refused
 * with exit 2 and exactly one stderr line, with no exception text and no stack frame. Of these
 * 40 lines the code before this test mishandled 12 (stack traces, runs of minutes, silent
 * wrong answers, two-line errors, exit 1).
 */
class CommandFuzzTest {

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {
        "aim --distance 100 --vx 1e-45",
        "aim --distance 100 --vx 20 --g 3e38",
        "aim --distance 100 --vx 20 --g 1e38 --method iterative",
        "aim --distance 100 --vx 20 --g 3e38 --tpf 1e-3 --method discrete",
        "aim --distance 100 --vx 20 --tpf 1e-9",
        "aim --distance 100 --vx 20 --tpf 1e-45",
        "aim --distance 100 --vx 20 --tpf 1e-7",
        "aim --distance 3e38 --vx 20",
        "aim --distance 1e-45 --vx 3e38",
        "aim --distance 100 --vx 3e38 --g 1e-45",
        "aim --distance 100 --vx 20 --mass 1e-39",
        "aim --distance 100 --vx 20 --mass 1e-39 --linear-drag 1",
        "aim --distance 100 --vx 20 --quadratic-drag 3e38 --method iterative",
        "aim --distance 100 --vx 20 --method iterative --tolerance 1e-45",
        "aim --distance 1/0 --vx 20",
        "aim --distance 0x10 --vx 20",
        "aim --distance 1e39 --vx 20",
        "aim --distance 1// --vx 20",
        "aim --distance . --vx 20",
        "aim --distance e5 --vx 20",
        "aim --distance 1e --vx 20",
        "aim --distance 100 --vx 20 --tpf 1/0",
        "trajectory --steps 10 --p0 3e38,0,0 --v0 3e38,0,0",
        "trajectory --steps 10 --v0 3e38,3e38,3e38 --quadratic-drag 1",
        "trajectory --steps 10 --mass 1e-39",
        "trajectory --steps 10 --mass 1e-39 --linear-drag 1",
        "trajectory --steps 10 --g 0,-3e38,0 --tpf 10",
        "trajectory --steps 1000 --linear-drag 10 --tpf 5",
        "trajectory --tpf 1e-7 --p0 1000,0,0 --steps 3",
        "trajectory --tpf 1e-45 --steps 3 --p0 1,1,1",
        "trajectory --duration 3e38",
        "trajectory --until-ground --g 0,0,0",
        "trajectory --steps 99999999999999999999",
        "trajectory --steps 10 --p0 1,2,3,4",
        "trajectory --steps 10 --v0 ,,",
        "demo --frames 0",
        "demo --fixed-tpf 0",
        "demo nosuch",
        "report --quick --tiny",
        "help nosuch",
    })
    void hostileCommandLineIsOneLineAndExitTwo(String commandLine) {
        CommandRun run = CommandRun.of(commandLine.split(" "));
        assertEquals(UsageException.EXIT_CODE, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertFalse(run.err.contains("at particlelab"), run.toString());
    }
}
