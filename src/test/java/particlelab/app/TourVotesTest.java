package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 34 §1, the room's votes without a window: a vote counts only its answers and only
 * until the reveal, its split and its CSV row say what was cast, and {@code tour --votes}
 * keeps the project's file rules (no overwrite without --force, no link written through, a
 * refused command line creates nothing). {@link TourVoteHeadlessTest} votes in the window.
 */
class TourVotesTest {

    /** Stop 8, the pull at h = 1/60 s: "Euler lands short, on, or long ...". */
    private static final int PULL_STOP = 7;

    @Test
    void aVoteCountsItsAnswersUntilTheReveal() {
        TourVote vote = pullVote();
        assertTrue(vote.vote(0));
        assertTrue(vote.vote(0));
        assertTrue(vote.vote(2));
        assertFalse(vote.vote(3), "the question has three answers");
        assertFalse(vote.vote(-1));
        assertEquals(3, vote.countVotes());
        vote.reveal();
        assertFalse(vote.vote(1), "the vote is over once revealed");
        assertEquals(2, vote.getCount(0));
        assertEquals(0, vote.getCount(1));
        assertEquals(1, vote.getCount(2));
    }

    @Test
    void theSplitGivesEachAnswersShareAndMarksTheRightOne() {
        TourVote vote = pullVote();
        vote.vote(0);
        vote.vote(0);
        vote.vote(2);
        assertEquals("the room (3 votes):  [1 short] 2 (67 %)   2 on 0 (0 %)   3 long 1 (33 %)\n",
                vote.appendSplit(new StringBuilder()).toString());
        TourVote none = pullVote();
        assertEquals("the room (0 votes):  [1 short] 0 (0 %)   2 on 0 (0 %)   3 long 0 (0 %)\n",
                none.appendSplit(new StringBuilder()).toString());
    }

    @Test
    void theCsvRowQuotesTheQuestionAndJoinsAnswersAndCounts() {
        TourVote vote = pullVote();
        vote.vote(1);
        vote.vote(0);
        assertEquals("8,\"Euler lands short, on, or long of the exact landing?\","
                + "short|on|long,1|1|0,short", vote.toCsvRow());
        assertEquals("\"say \"\"hi\"\"\"", TourVote.csvCell("say \"hi\""));
    }

    @Test
    void theVotesFileHoldsTheHeaderAndOneRowPerRevealAndRefusesALink(@TempDir Path temp)
            throws IOException {
        Path file = temp.resolve("votes.csv");
        VotesFile votes = new VotesFile(file, false);
        TourVote first = pullVote();
        first.vote(0);
        votes.record(first);
        TourVote second = pullVote();
        second.vote(2);
        votes.record(second);
        assertEquals(TourVote.CSV_HEADER + "\n" + first.toCsvRow() + "\n" + second.toCsvRow()
                + "\n", new String(Files.readAllBytes(file), StandardCharsets.UTF_8));
        // A link planted where the file was is never written through.
        Path target = temp.resolve("elsewhere.txt");
        Files.write(target, new byte[] {'x'});
        Files.delete(file);
        Files.createSymbolicLink(file, target);
        assertThrows(IOException.class, () -> votes.record(pullVote()));
        assertEquals("x", new String(Files.readAllBytes(target), StandardCharsets.UTF_8));
    }

    @Test
    void anExistingVotesFileIsRefusedWithoutForceBeforeTheWindow(@TempDir Path temp)
            throws IOException {
        Path file = temp.resolve("votes.csv");
        Files.write(file, new byte[] {'k'});
        CommandRun run = CommandRun.of("tour", "--votes", file.toString());
        assertEquals(Program.USAGE, run.code, run.toString());
        assertTrue(run.err.startsWith("particle-lab tour: --votes: ") && run.err.contains(
                "exists; use --force"), run.err);
        assertEquals(1, run.err.split("\n").length, run.err);
        assertEquals("k", new String(Files.readAllBytes(file), StandardCharsets.UTF_8));
    }

    @Test
    void aLinkOrAMissingFolderIsRefusedAndNothingIsCreated(@TempDir Path temp)
            throws IOException {
        Path target = temp.resolve("target.csv");
        Files.write(target, new byte[] {'k'});
        Path link = Files.createSymbolicLink(temp.resolve("link.csv"), target);
        CommandRun linked = CommandRun.of("tour", "--votes", link.toString(), "--force");
        assertEquals(Program.USAGE, linked.code, linked.toString());
        assertTrue(linked.err.contains("is a symbolic link"), linked.err);
        Path missing = temp.resolve("no-such-folder").resolve("votes.csv");
        CommandRun away = CommandRun.of("tour", "--votes", missing.toString());
        assertEquals(Program.USAGE, away.code, away.toString());
        assertTrue(away.err.contains("must exist"), away.err);
        assertFalse(Files.exists(missing.getParent()));
        CommandRun folder = CommandRun.of("tour", "--votes", temp.toString());
        assertEquals(Program.USAGE, folder.code, folder.toString());
        assertTrue(folder.err.contains("is a folder"), folder.err);
        assertEquals("k", new String(Files.readAllBytes(target), StandardCharsets.UTF_8));
    }

    private static TourVote pullVote() {
        TourQuestion question = TourQuestions.forStop(PULL_STOP);
        return new TourVote(PULL_STOP, question, question.answer(TourCommand.stateOf(
                PULL_STOP)));
    }
}
