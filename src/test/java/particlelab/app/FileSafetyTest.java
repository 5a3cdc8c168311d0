package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.TrajectoryRecord;

/**
 * Issue 17, part 5: {@code demo --export}, {@code report --out} and {@code --screenshot} never
 * overwrite a file without {@code --force} and never write through a symbolic link planted in
 * the folder, not even with it; a refused command line says so in one line, before any work,
 * and leaves no folder behind. Part 7: the reasons given for /proc, a folder as --jmh and a
 * device as --screenshot are the true ones.
 */
class FileSafetyTest {

    /** What a user (or an intruder) left in the folder, to check it was not touched. */
    private static final String PLANTED = "the user's own data\n";
    private static final String CSV = "gravity-only.csv";

    @Test
    void anExportOverAnExistingCsvIsRefusedUnlessForced(@TempDir Path temp) throws IOException {
        Path folder = Files.createDirectory(temp.resolve("out"));
        Path planted = Files.writeString(folder.resolve(CSV), PLANTED);
        CommandRun refused = exportDrag(folder);
        assertRefused(refused, "--export", planted.toString());
        assertTrue(refused.err.contains("--force"), refused.toString());
        assertEquals(PLANTED, Files.readString(planted));
        CommandRun forced = exportDrag(folder, "--force");
        assertEquals(0, forced.code, forced.toString());
        assertTrue(Files.readString(planted).startsWith(TrajectoryRecord.HEADER),
                "replaced with the trajectory");
    }

    @Test
    void anExportNeverWritesThroughAPlantedLinkEvenForced(@TempDir Path temp)
            throws IOException {
        Path folder = Files.createDirectory(temp.resolve("shared"));
        Path victim = Files.writeString(temp.resolve("bashrc"), PLANTED);
        Path link = Files.createSymbolicLink(folder.resolve(CSV), victim);
        for (String[] extra : new String[][] {{}, {"--force"}}) {
            CommandRun run = exportDrag(folder, extra);
            assertRefused(run, "--export", link.toString());
            assertTrue(run.err.contains("symbolic link"), run.toString());
            assertEquals(PLANTED, Files.readString(victim));
            assertTrue(Files.isSymbolicLink(link));
        }
        // A dangling link is refused as well: following it would create the file elsewhere.
        Path elsewhere = temp.resolve("elsewhere.csv");
        Files.delete(link);
        Files.createSymbolicLink(link, elsewhere);
        assertRefused(exportDrag(folder, "--force"), "--export", link.toString());
        assertFalse(Files.exists(elsewhere));
    }

    @Test
    void theExportFolderMayBeALinkTheUserNamed(@TempDir Path temp) throws IOException {
        Path real = Files.createDirectory(temp.resolve("real"));
        Path named = Files.createSymbolicLink(temp.resolve("named"), real);
        CommandRun run = exportDrag(named);
        assertEquals(0, run.code, run.toString());
        assertTrue(Files.isRegularFile(real.resolve(CSV)));
    }

    @Test
    void aRefusedCommandLineLeavesNoFolderBehind(@TempDir Path temp) {
        Path top = temp.resolve("newdir");
        CommandRun export = CommandRun.of("demo", "drag", "--frames", "1", "--export",
                top.resolve("deeper").toString(), "--set", "zz=1");
        assertRefused(export, "--set", "zz=1");
        assertFalse(Files.exists(top), "--export created " + top);
        CommandRun shot = CommandRun.of("demo", "drag", "--frames", "1", "--screenshot",
                top.resolve("deeper/x.png").toString(), "--set", "zz=1");
        assertRefused(shot, "--set", "zz=1");
        assertFalse(Files.exists(top), "--screenshot created " + top);
        CommandRun unknown = CommandRun.of("demo", "nosuchdemo", "--frames", "1", "--export",
                top.toString());
        assertEquals(2, unknown.code, unknown.toString());
        assertFalse(Files.exists(top), "an unknown demo still created " + top);
    }

    @Test
    void aScreenshotOverAnExistingFileOrLinkIsRefusedBeforeTheWindow(@TempDir Path temp)
            throws IOException {
        Path existing = Files.writeString(temp.resolve("shot.png"), PLANTED);
        CommandRun run = CommandRun.of("demo", "drag", "--frames", "1", "--screenshot",
                existing.toString());
        assertRefused(run, "--screenshot", existing.toString());
        assertTrue(run.err.contains("--force"), run.toString());
        assertEquals(PLANTED, Files.readString(existing));
        Path victim = Files.writeString(temp.resolve("victim"), PLANTED);
        Path link = Files.createSymbolicLink(temp.resolve("link.png"), victim);
        run = CommandRun.of("demo", "drag", "--frames", "1", "--screenshot", link.toString(),
                "--force");
        assertRefused(run, "--screenshot", link.toString());
        assertTrue(run.err.contains("symbolic link"), run.toString());
        assertEquals(PLANTED, Files.readString(victim));
        // With --force an existing regular file passes the check (the window then writes it).
        DemoCommand.checkScreenshotPath(existing.toString(), true);
    }

    /**
     * The PNG itself is written create-new too, so a file or link planted between the check
     * and the last frame is not overwritten or followed.
     */
    @Test
    void theScreenshotWriteRefusesWhatWasPlantedAfterTheCheck(@TempDir Path temp)
            throws IOException {
        BufferedImage image = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        Path file = Files.writeString(temp.resolve("shot.png"), PLANTED);
        assertThrows(IOException.class, () -> ScreenshotCapture.writePng(image, file, false));
        assertEquals(PLANTED, Files.readString(file));
        ScreenshotCapture.writePng(image, file, true);
        assertEquals(2, ImageIO.read(file.toFile()).getWidth());
        Path victim = Files.writeString(temp.resolve("victim"), PLANTED);
        Path link = Files.createSymbolicLink(temp.resolve("link.png"), victim);
        assertThrows(IOException.class, () -> ScreenshotCapture.writePng(image, link, true));
        assertEquals(PLANTED, Files.readString(victim));
    }

    @Test
    void aDeviceAsTheScreenshotIsRefusedBeforeTheWindow() {
        Path device = Paths.get("/dev/full");
        if (!Files.exists(device)) {
            return;
        }
        CommandRun run = CommandRun.of("demo", "drag", "--frames", "1", "--screenshot",
                device.toString(), "--force");
        assertRefused(run, "--screenshot", "/dev/full");
        assertTrue(run.err.contains("device"), run.toString());
    }

    @Test
    void aReportOverExistingFilesOrLinksIsRefusedBeforeAnyWork(@TempDir Path temp)
            throws IOException {
        Path folder = Files.createDirectory(temp.resolve("report"));
        Path index = Files.writeString(folder.resolve("index.md"), PLANTED);
        CommandRun run = CommandRun.of("report", "--tiny", "--out", folder.toString());
        assertRefused(run, "--out", index.toString());
        assertTrue(run.err.contains("--force"), run.toString());
        assertEquals(PLANTED, Files.readString(index));
        Files.delete(index);
        Path victim = Files.writeString(temp.resolve("victim"), PLANTED);
        for (String name : List.of("orders.csv", "aiming.csv")) {
            Path link = Files.createSymbolicLink(folder.resolve(name), victim);
            run = CommandRun.of("report", "--tiny", "--force", "--out", folder.toString());
            assertRefused(run, "--out", link.toString());
            assertTrue(run.err.contains("symbolic link"), run.toString());
            assertEquals(PLANTED, Files.readString(victim));
            Files.delete(link);
        }
        // Refused before the work started: the report wrote none of its files.
        try (var left = Files.list(folder)) {
            assertEquals(0, left.count());
        }
    }

    @Test
    void aForcedReportReplacesItsOwnFiles(@TempDir Path temp) throws IOException {
        Path folder = Files.createDirectory(temp.resolve("report"));
        Path index = Files.writeString(folder.resolve("index.md"), PLANTED);
        CommandRun run = CommandRun.of("report", "--tiny", "--force", "--out",
                folder.toString());
        assertEquals(0, run.code, run.toString());
        String text = Files.readString(index);
        assertFalse(text.contains(PLANTED.trim()), "index.md kept the old text");
        assertTrue(text.startsWith("#"), text);
    }

    @Test
    void procIsRefusedAsNotWritableNotAsMissing() {
        if (!Files.isDirectory(Paths.get("/proc"))) {
            return;
        }
        CommandRun run = CommandRun.of("report", "--tiny", "--out", "/proc");
        assertRefused(run, "--out", "/proc");
        assertFalse(run.err.contains("no such file"), run.toString());
        assertTrue(run.err.contains("not writable"), run.toString());
    }

    @Test
    void aFolderAsJmhIsNamedAFolder(@TempDir Path temp) {
        CommandRun run = CommandRun.of("report", "--tiny", "--jmh", temp.toString(), "--out",
                temp.resolve("out").toString());
        assertRefused(run, "--jmh", temp.toString());
        assertTrue(run.err.contains("is a folder"), run.toString());
        assertFalse(run.err.contains("does not exist"), run.toString());
    }

    private static CommandRun exportDrag(Path folder, String... extra) {
        String[] args = {"demo", "drag", "--frames", "3", "--fixed-tpf", "0.016666668",
            "--export", folder.toString()};
        String[] all = new String[args.length + extra.length];
        System.arraycopy(args, 0, all, 0, args.length);
        System.arraycopy(extra, 0, all, args.length, extra.length);
        return CommandRun.of(all);
    }

    /** Exit 2, nothing on stdout, one line on stderr naming the option and the target. */
    private static void assertRefused(CommandRun run, String option, String target) {
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(option), run.toString());
        assertTrue(run.err.contains(target), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
    }
}
