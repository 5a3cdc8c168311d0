package particlelab.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.coursework.AimingExercise;
import particlelab.coursework.ImpulseExercise;
import particlelab.coursework.QuadraticDragExercise;
import particlelab.coursework.RecipeExercise;
import particlelab.coursework.RotationExercise;
import particlelab.coursework.SweptPlaneExercise;

/**
 * The grader graded: the reference solutions score Y/Y, the stubs 0/Y, and each mutant (a
 * mistake students make) fails exactly the check meant to catch it, with the lecture's words.
 * This is how `gradle test`, and so CI, runs the grading of the solutions.
 */
class GradingTest {

    private static final String SOLUTIONS = "particlelab.solutions";
    private static final String STUBS = "particlelab.exercises";

    @Test
    void solutionsScoreFullMarks() {
        List<Grader.Result> results = Grader.grade(new Submission(SOLUTIONS), 0);
        assertEquals(List.of(), failures(results));
        String table = table(results);
        assertTrue(table.endsWith("score: " + results.size() + "/" + results.size() + "\n"),
                table);
    }

    @Test
    void stubsScoreZeroAndSayNotWrittenYet() {
        List<Grader.Result> results = Grader.grade(new Submission(STUBS), 0);
        for (Grader.Result result : results) {
            assertEquals(Grader.NOT_WRITTEN, result.mistake(),
                    result.exercise().className() + " " + result.check().name());
        }
        assertTrue(table(results).endsWith("score: 0/" + results.size() + "\n"));
    }

    @Test
    void everyExerciseIsWorthSomethingAndTheSetCoversEightExercises() {
        assertEquals(8, Exercises.ALL.size());
        for (int i = 0; i < Exercises.ALL.size(); ++i) {
            assertEquals(i + 1, Exercises.ALL.get(i).number());
            assertTrue(Exercises.ALL.get(i).checks().size() >= 2, Exercises.ALL.get(i).slide());
        }
    }

    static Stream<Arguments> mutants() {
        return Stream.of(
                mutant(RecipeExercise.class, Mutants.PositionFirst::new, "Recipe/order",
                        "P was updated before V: your shot lands vx·h long"),
                mutant(QuadraticDragExercise.class, Mutants.SlideDrag::new,
                        "QuadraticDrag/magnitude", "you wrote the slide's -c|V|^2 V"),
                mutant(AimingExercise.class, Mutants.ContinuousAim::new, "Aiming/discrete",
                        "you fired the continuous aim"),
                mutant(ImpulseExercise.class, Mutants.NoRestitution::new,
                        "Impulse/restitution", "the impulse lacks its (1+e)"),
                mutant(SweptPlaneExercise.class, Mutants.OverlapOnly::new,
                        "SweptPlane/never misses", "an overlap test looks only at the step's end"),
                mutant(RotationExercise.class, Mutants.NoR::new, "Rotation/euler step",
                        "you added h·ω̃ without R"));
    }

    @ParameterizedTest(name = "{2}")
    @MethodSource("mutants")
    <T> void eachMutantFailsExactlyItsCheck(Class<T> contract, Supplier<T> mutant,
            String expectedFailure, String expectedWords) {
        Submission submission = new Submission(SOLUTIONS).replace(contract, mutant);
        List<Grader.Result> results = Grader.grade(submission, 0);
        assertEquals(List.of(expectedFailure), failures(results));
        String mistake = results.stream().filter(r -> !r.passed()).findFirst().get().mistake();
        assertTrue(mistake.contains(expectedWords), mistake);
    }

    @Test
    void studentCodeThatThrowsIsOneLineWithItsMessage() {
        Submission submission = new Submission(SOLUTIONS).replace(RecipeExercise.class,
                () -> (p, v, m, g, b, t, h) -> {
                    throw new IllegalStateException("forgot the mass");
                });
        List<Grader.Result> results = Grader.grade(submission, 1);
        for (Grader.Result result : results) {
            assertEquals("threw IllegalStateException: forgot the mass", result.mistake());
        }
    }

    @Test
    void aThrowNamesTheLineOfTheStudentsFile() {
        // Graded as if this test's package were the student's: the line found is this file's.
        Submission submission = new Submission("particlelab.grading").replace(
                RecipeExercise.class, () -> (p, v, m, g, b, t, h) -> {
                    throw new ArithmeticException("/ by zero");
                });
        String mistake = Grader.grade(submission, 1).get(0).mistake();
        assertTrue(mistake.matches("threw ArithmeticException: / by zero"
                + " \\(GradingTest\\.java:\\d+\\)"), mistake);
    }

    @Test
    void thePagesGradeTranscriptsAreWhatTheGraderPrints() throws IOException {
        // docs/exercises.md shows `$ gradle -q grade ...` and its output in fenced blocks.
        String page = Files.readString(Paths.get("docs", "exercises.md"));
        String[] blocks = page.split("```\n");
        int compared = 0;
        for (String block : blocks) {
            if (!block.startsWith("$ gradle -q grade")) {
                continue;
            }
            String command = block.substring(0, block.indexOf('\n'));
            String shown = block.substring(command.length() + 1);
            boolean solutions = command.contains("-Psolutions");
            int only = command.contains("-Pexercise=")
                    ? Integer.parseInt(command.replaceAll(".*-Pexercise=(\\d+).*", "$1")) : 0;
            Submission submission = new Submission(solutions ? SOLUTIONS : STUBS);
            assertEquals(table(Grader.grade(submission, only)), shown, command);
            ++compared;
        }
        assertEquals(3, compared, "the page's three grade transcripts");
    }

    @Test
    void studentCodeThatReturnsNanFailsWithoutSpreadingIt() {
        Submission submission = new Submission(SOLUTIONS).replace(RecipeExercise.class,
                () -> (p, v, m, g, b, t, h) -> {
                    v.divideLocal(0f).multLocal(0f);   // 0/0 and ∞·0: NaN in every component
                    p.addLocal(v);
                });
        List<Grader.Result> results = Grader.grade(submission, 1);
        assertEquals(3, results.size());
        for (Grader.Result result : results) {
            assertTrue(result.mistake().contains("NaN"), result.mistake());
        }
    }

    @Test
    void studentCodeThatNeverReturnsFailsItsCheckAndTheOtherCheckIsGraded() {
        // A loop that sleeps rather than spins, so the thread left behind costs no CPU.
        Submission submission = new Submission(SOLUTIONS).replace(AimingExercise.class,
                () -> new AimingExercise() {
                    @Override
                    public float continuousVy(float vx, float rangeM, float gravity) {
                        return gravity * rangeM / (2f * vx);
                    }

                    @Override
                    public float discreteVy(float vx, float range, float gravity, float h) {
                        while (true) {
                            try {
                                Thread.sleep(60_000L);
                            } catch (InterruptedException e) {
                                Thread.currentThread().interrupt();
                            }
                        }
                    }
                });
        // Exercise 3 alone: loading the demo framework for exercise 8 may take longer than
        // this test's short limit on a busy machine (the real limit is 10 s).
        List<Grader.Result> results = Grader.grade(submission, 3, 200L);
        assertEquals(List.of("Aiming/discrete"), failures(results));
        assertTrue(results.stream().anyMatch(r -> "did not return within 0.2 s: an endless loop?"
                .equals(r.mistake())));
    }

    @Test
    void oneExerciseCanBeGradedAlone() {
        List<Grader.Result> results = Grader.grade(new Submission(SOLUTIONS), 3);
        assertEquals(2, results.size());
        assertTrue(table(results).endsWith("score: 2/2\n"));
    }

    @Test
    void aMissingClassIsNamed() {
        List<Grader.Result> results = Grader.grade(new Submission("particlelab.nowhere"), 2);
        assertTrue(results.get(0).mistake().startsWith("no class particlelab.nowhere."
                + "QuadraticDrag"), results.get(0).mistake());
    }

    private static <T> Arguments mutant(Class<T> contract, Supplier<T> mutant, String failure,
            String words) {
        return Arguments.of(contract, mutant, failure, words);
    }

    private static List<String> failures(List<Grader.Result> results) {
        List<String> failed = new ArrayList<>();
        for (Grader.Result result : results) {
            if (!result.passed()) {
                failed.add(result.exercise().className() + "/" + result.check().name());
            }
        }
        return failed;
    }

    private static String table(List<Grader.Result> results) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        Grader.print(results, new PrintStream(bytes, true, StandardCharsets.UTF_8));
        return bytes.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n");
    }
}
