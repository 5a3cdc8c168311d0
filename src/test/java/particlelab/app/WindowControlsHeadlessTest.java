package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.event.KeyInputEvent;
import com.jme3.math.Vector3f;
import com.jme3.system.JmeContext;
import com.simsilica.lemur.GuiGlobals;
import java.lang.reflect.Field;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.TrajectoryExport;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.AudioNodeSoundPlayer;
import particlelab.view.CollisionSounds;
import particlelab.view.HudLayout;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.SilentSoundPlayer;
import particlelab.view.SoundCue;
import particlelab.view.SoundLog;
import particlelab.view.SoundPlayer;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * The window and its controls in a real headless application on the catalogue's demos: a
 * reshape (the camera resized, as jME does on every window resize) and a new HUD factor lay
 * the shown demo out again on the next frame, down to the smallest window and back; the keys
 * are in every demo's help; fullscreen without a window says so; F8's presentation mode stays
 * on across demos and tour stops; demos are chosen with real key events; sounds without an
 * audio device; the E key's export folder.
 */
class WindowControlsHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] SEQUENCE = {{640, 360}, {400, 300},
        {HudLayout.MIN_WIDTH, HudLayout.MIN_HEIGHT}, {1280, 720}};
    private static final int FRAMES_BETWEEN = 3;
    /** Links are planted for this many seconds' folder names from now on. */
    private static final int PLANTED_SECONDS = 30;
    private static final DateTimeFormatter STAMP =
            DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void aReshapeAndANewHudFactorLayTheShownDemoOutOnTheNextFrame() throws Exception {
        ParticleLabApp app = harness.app();
        DemoState demo = harness.call(() -> app.getSwitcher().getSelected());
        harness.call(() -> {
            app.getCamera().resize(1920, 1080, true);
            return true;
        });
        harness.awaitFrames(2);
        assertTrue(harness.call(() -> demo.getDemoHud().isLaidOutFor(1920, 1080, 1f)));
        assertEquals(1920f, harness.call(() -> demo.getWindow().getHud().getLayout().getWindow()
                .getWidth()));
        assertEquals(HudLayout.scaleFor(1920, 1080),
                harness.call(() -> demo.getWindow().getHud().getLayout().getScale()));

        harness.call(() -> {
            app.getWindowControls().setUiFactor(0.5f);
            return true;
        });
        harness.awaitFrames(2);
        assertTrue(harness.call(() -> demo.getDemoHud().isLaidOutFor(1920, 1080, 0.5f)));
        assertEquals(0.5f * HudLayout.scaleFor(1920, 1080),
                harness.call(() -> demo.getWindow().getHud().getLayout().getScale()));

        harness.call(() -> {
            app.getWindowControls().setUiFactor(1f);
            app.getCamera().resize(1280, 720, true);
            return true;
        });
        harness.awaitFrames(2);
        assertTrue(harness.call(() -> demo.getDemoHud().isLaidOutFor(1280, 720, 1f)));
    }

    @Test
    void showingThePanelKeepsTheUsersHudFactor() throws Exception {
        ParticleLabApp app = harness.app();
        DemoState demo = harness.call(() -> app.getSwitcher().getSelected());
        harness.call(() -> {
            app.getWindowControls().setUiFactor(1.5f);
            return true;
        });
        harness.awaitFrames(2);
        int width = harness.call(() -> app.getCamera().getWidth());
        int height = harness.call(() -> app.getCamera().getHeight());
        try {
            // F2 lays the HUD out again for the panel's slot, at once, within the key press:
            // at the factor in use, not at 1 until the window controls notice a frame later.
            for (int press = 0; press < 2; ++press) {
                assertTrue(harness.call(() -> {
                    HeadlessHarness.press(demo, "F2");
                    return demo.getDemoHud().isLaidOutFor(width, height, 1.5f);
                }), "press " + press);
            }
        } finally {
            harness.call(() -> {
                app.getWindowControls().setUiFactor(1f);
                return true;
            });
            harness.awaitFrames(2);
        }
    }

    @Test
    void theWindowAndExportKeysAreInEveryDemosHelp() throws Exception {
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            String help = demo.getKeys().getHelpText();
            for (String line : new String[] {"F11  -  fullscreen", "F10  -  larger HUD text",
                "F9  -  smaller HUD text", "F8  -  presentation mode", "E  -  export"}) {
                assertTrue(help.contains(line), demo.getTitle() + " lacks " + line);
            }
        }
    }

    @Test
    void fullscreenWithoutAWindowSaysSo() throws Exception {
        ParticleLabApp app = harness.app();
        KeyBinding f11 = null;
        for (KeyBinding binding : app.getSwitcher().getBindings()) {
            if (binding.getKeyCode(0) == KeyInput.KEY_F11) {
                f11 = binding;
            }
        }
        KeyBinding key = f11;
        harness.call(() -> {
            key.press(0);
            return true;
        });
        harness.awaitFrames(2);
        assertEquals("fullscreen needs a window (this run has none)",
                harness.call(() -> app.getSwitcher().getSelected().getDemoHud().getNotice()));
    }

    @Test
    void f8PresentsEveryDemoAndStaysOnAcrossDemosAndTourStops() throws Exception {
        ParticleLabApp app = harness.app();
        KeyBinding f8 = find(app, KeyInput.KEY_F8);
        DemoSwitcher switcher = app.getSwitcher();
        try {
            harness.call(() -> {
                f8.press(0);
                return true;
            });
            harness.awaitFrames(2);
            assertTrue(harness.call(() -> switcher.getSelected().getDemoHud().isPresenting()));
            assertTrue(harness.call(() -> switcher.getSelected().getWindow().getHud().getLayout()
                    .isPresenting()));
            // Tab, a digit (select) and a tour stop: each demo shown opens presenting.
            for (int next : new int[] {1, 8}) {
                harness.call(() -> {
                    switcher.select(next);
                    return true;
                });
                harness.awaitFrames(3);
                assertEquals(next, (int) harness.call(() -> switcher.getDemos()
                        .indexOf(switcher.getSelected())));
                assertTrue(harness.call(() -> switcher.getSelected().getDemoHud().isPresenting()),
                        "demo " + (next + 1));
            }
            harness.call(() -> {
                app.getTour().go(2);
                return true;
            });
            harness.awaitFrames(3);
            assertTrue(harness.call(() -> switcher.getSelected().getDemoHud().isPresenting()));
            assertTrue(harness
                    .call(() -> switcher.getSelected().getWindow().getHud().getFooterText()
                    .contains("PageDown  next stop")));
            // F8 again: the full HUD, for the demo shown and the next one.
            harness.call(() -> {
                f8.press(0);
                return true;
            });
            harness.awaitFrames(2);
            assertFalse(harness.call(() -> switcher.getSelected().getDemoHud().isPresenting()));
            harness.call(() -> {
                app.getTour().leave();
                switcher.select(0);
                return true;
            });
            harness.awaitFrames(3);
            assertFalse(harness.call(() -> switcher.getSelected().getDemoHud().isPresenting()));
        } finally {
            harness.call(() -> {
                app.getTour().leave();
                app.getWindowControls().setPresenting(false);
                switcher.select(0);
                return true;
            });
            harness.awaitFrames(3);
        }
    }

    /**
     * Issue 17: a running window resized to 400x300 died. Each catalogue demo in turn, shown
     * in the window that opened at 1280x720, has its window (the camera, as jME resizes it on
     * a reshape) taken down to the smallest size {@code --window} accepts and back, with
     * frames of jME's loop between: each size is laid out by the next frames, with the scene
     * inside the window, and back at 1280x720 the layout is the one the fresh window had (a
     * band grown on the small window gives its lines back).
     */
    @Test
    void everyDemoSurvivesAResizeDownToTheSmallestWindowAndComesBackAsFresh()
            throws Exception {
        ParticleLabApp app = harness.app();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count; ++index) {
            int chosen = index;
            harness.call(() -> {
                app.getSwitcher().select(chosen);
                return true;
            });
            harness.awaitFrames(FRAMES_BETWEEN);
            DemoState demo = app.getSwitcher().getDemos().get(index);
            String fresh = harness.call(() -> describe(demo));
            for (int[] size : SEQUENCE) {
                harness.call(() -> {
                    app.getCamera().resize(size[0], size[1], true);
                    return true;
                });
                harness.awaitFrames(FRAMES_BETWEEN);
                String where = demo.getTitle() + " at " + size[0] + "x" + size[1];
                assertTrue(harness.call(() -> demo.getDemoHud().isLaidOutFor(size[0], size[1], 1f)), where);
                ScreenRect scene = harness
                        .call(() -> demo.getWindow().getHud().getLayout().getScene());
                assertTrue(!scene.isEmpty() && new ScreenRect(0f, 0f, size[0], size[1])
                        .contains(scene), where + ": scene " + scene);
            }
            assertEquals(fresh, harness.call(() -> describe(demo)), demo.getTitle());
        }
    }

    /**
     * Choosing demos with real key events: each press and release goes through jME's input
     * manager (its queue, the key triggers, the switcher's mappings and its Shift tracking),
     * as the keyboard's would. The harness's frame time is 0, so a lone 1's wait is passed
     * by hand; the two-digit numbers complete at their second digit ({@code
     * DemoSwitcherTest} covers the wait).
     */
    @Test
    void digitsTabAndShiftTabReachEveryDemoInLectureOrder() throws Exception {
        tap(KeyInput.KEY_1);
        tap(KeyInput.KEY_2);
        assertEquals(12, selectedNumber(), "1 then 2");

        shiftTab(KeyInput.KEY_LSHIFT);
        assertEquals(11, selectedNumber(), "Shift+Tab");
        shiftTab(KeyInput.KEY_RSHIFT);
        assertEquals(10, selectedNumber(), "Shift+Tab with the right Shift");
        tap(KeyInput.KEY_TAB);
        assertEquals(11, selectedNumber(), "Tab after Shift was released");

        tap(KeyInput.KEY_1);
        tap(KeyInput.KEY_9);
        assertEquals(19, selectedNumber(), "1 then 9");
        tap(KeyInput.KEY_TAB);
        assertEquals(1, selectedNumber(), "Tab wraps from the last demo to the first");
        shiftTab(KeyInput.KEY_LSHIFT);
        assertEquals(19, selectedNumber(), "Shift+Tab wraps back");

        tap(KeyInput.KEY_4);
        assertEquals(4, selectedNumber(), "4 chooses at once");
        // Every demo, by number, in lecture order.
        for (int number = 1; number <= demos().size(); ++number) {
            if (number >= 10) {
                tap(KeyInput.KEY_1);
                tap(digitKey(number % 10));
            } else {
                tap(digitKey(number));
                if (number == 1) {
                    // A lone 1 waits for a second digit, and the title says so; let its
                    // wait pass by hand.
                    assertTrue(harness.call(() -> harness.app().getSwitcher().isEntryPending()));
                    String title = harness.call(() -> harness.app().getSwitcher().getSelected()
                            .getWindow().getHud().getTitleText());
                    assertEquals("4.  " + demos().get(3).getTitle()
                            + "      typed 1_  (a second digit for 10-19)", title);
                    harness.call(() -> {
                        harness.app().getSwitcher().update(DemoSwitcher.ENTRY_SECONDS);
                        return true;
                    });
                }
            }
            assertEquals(number, selectedNumber());
        }
    }

    @Test
    void theHelpAndFooterSayHowToChooseADemo() throws Exception {
        DemoState demo = harness.call(() -> harness.app().getSwitcher().getSelected());
        String help = demo.getKeys().getHelpText();

        assertTrue(help.contains("\nChoosing a demo\n   0-9  -  type a demo's number (1-19):"),
                help);
        assertTrue(help.contains("\n   Tab / Shift+Tab  -  next demo; with Shift, the previous"
                + " one"), help);
        assertTrue(help.contains("\nThe demos, by number\n   1  -  " + demos().get(0).getTitle()
                + ";   2  -  " + demos().get(1).getTitle() + "\n"), help);
        assertTrue(help.contains("\n   19  -  " + demos().get(18).getTitle() + "\n"), help);
        String footer = harness.call(() -> demo.getWindow().getHud().getFooterText());
        assertTrue(footer.contains("Tab / Shift+Tab  demos (or 1-19)"), footer);
    }

    /**
     * No audio device: in a running application without an audio renderer, as the launcher
     * starts the window when {@code AudioProbe} finds no device, sounds are recorded and
     * shown, never played, and nothing fails.
     */
    @Test
    void noAudioRendererMeansTheSilentPlayerAndNothingFails() throws Exception {
        Object[] result = harness.call(() -> {
            ParticleLabApp app = harness.app();
            SoundPlayer player = SoundPlayer.forApplication(app);
            // A dropped ball that is destroyed at its first bounce: impact and destroy sounds.
            World world = new World();
            world.addRule(SurfaceRule.ground(new ImpulseResponse(0.5f), Detection.SWEPT));
            Body ball = world.addBody(new ParticleIntegrator(new Gravity()),
                    new Vector3f(0f, 1f, 0f), Vector3f.ZERO, 1f, 0.1f);
            world.addContactListener(new ContactListener() {
                @Override
                public void resolved(Contact contact, World w) {
                    w.destroy(ball);
                }
            });
            CollisionSounds sounds = new CollisionSounds(player);
            sounds.attach(world);
            for (int frame = 0; frame < 120; ++frame) {
                world.step(H);
                sounds.playFrame(world);
                world.getImpacts().clear();
            }
            sounds.detach(world);
            return new Object[] {app.getAudioRenderer(), player};
        });
        assertNull(result[0], "the headless test application has no audio renderer");
        SoundPlayer player = (SoundPlayer) result[1];
        assertInstanceOf(SilentSoundPlayer.class, player);
        assertFalse(player.isAudible());
        SoundLog log = player.getLog();
        assertEquals(2, log.getTotal(), "one impact, one destroy");
        assertSame(SoundCue.IMPACT, log.getCue(0));
        assertSame(SoundCue.DESTROY, log.getCue(1));
        assertEquals("sound: destroy vol 1.00 (no audio device)",
                log.appendLatest(new StringBuilder()).toString());
    }

    @Test
    void theAppsAssetManagerFindsTheSoundsButOnlyAnAudioRendererCanPlayThem() throws Exception {
        Object[] result = harness.call(() -> {
            AudioNodeSoundPlayer player =
                    new AudioNodeSoundPlayer(harness.app().getAssetManager());
            float seconds = player.getNode(SoundCue.DESTROY).getAudioData().getDuration();
            IllegalStateException refused = assertThrows(IllegalStateException.class,
                    () -> player.play(SoundCue.IMPACT, 0.5f));
            return new Object[] {seconds, refused.getMessage()};
        });
        // assets/ is on the runtime classpath: jME loaded Sounds/destroy.wav.
        assertEquals((float) SoundCue.DESTROY.getDurationSeconds(), (float) result[0], 1e-4f);
        // Why SoundPlayer.forApplication never picks jME's player without a renderer.
        assertTrue(((String) result[1]).startsWith("No audio renderer"), (String) result[1]);
    }

    /**
     * The E key's export ({@link ExportState}): each export gets a folder it made itself, so
     * a name taken by anything, a symbolic link planted there included, is passed over,
     * never written through.
     */
    @Test
    void aFolderNameTakenByAPlantedLinkIsPassedOver(@TempDir Path temp) throws Exception {
        Path base = Files.createDirectory(temp.resolve("exports"));
        ParticleLabApp app = harness.app();
        int dragIndex = DemoCatalog.indexOf("drag");
        DemoState drag = demos().get(dragIndex);
        String name = TrajectoryExport.fileSafeName(drag.getTitle());
        // Dangling links at the names the next seconds' exports would take: following one
        // would make the folder (and write the CSVs) elsewhere.
        Path elsewhere = temp.resolve("elsewhere");
        LocalDateTime now = LocalDateTime.now();
        for (int s = -1; s < PLANTED_SECONDS; ++s) {
            Files.createSymbolicLink(base.resolve(name + "-" + now.plusSeconds(s).format(STAMP)),
                    elsewhere.resolve(Integer.toString(s)));
        }
        ExportState export = new ExportState(app.getSwitcher(), base);
        try {
            harness.call(() -> {
                app.getSwitcher().select(dragIndex);
                return app.getStateManager().attach(export);
            });
            harness.awaitFrames(2);
            Path first = harness.call(export::exportNow);
            Path second = harness.call(export::exportNow);
            for (Path folder : List.of(first, second)) {
                assertFalse(Files.isSymbolicLink(folder), folder + " is a planted link");
                assertTrue(Files.isDirectory(folder), folder.toString());
                assertEquals(base, folder.getParent());
                assertTrue(Files.isRegularFile(folder.resolve("gravity-only.csv")),
                        "no CSV in " + folder);
                // the E key's export carries its settings too (issue 33)
                assertTrue(Files.isRegularFile(folder.resolve("parameters.csv")),
                        "no parameters.csv in " + folder);
            }
            assertNotEquals(first, second, "two exports shared a folder");
        } finally {
            harness.call(() -> {
                app.getStateManager().detach(export);
                app.getSwitcher().select(0);
                return true;
            });
            harness.awaitFrames(3);
        }
        assertFalse(Files.exists(elsewhere), "an export followed a planted link");
    }

    private static KeyBinding find(ParticleLabApp app, int keyCode) {
        for (KeyBinding binding : app.getSwitcher().getBindings()) {
            if (binding.getKeyCode(0) == keyCode) {
                return binding;
            }
        }
        throw new IllegalStateException("no application key " + keyCode);
    }

    /** @return the catalogue's demos, in the window (live) */
    private static List<DemoState> demos() {
        return harness.app().getSwitcher().getDemos();
    }

    /** Press and release a key, and let two frames handle it and switch. */
    private static void tap(int keyCode) throws Exception {
        key(keyCode, true);
        key(keyCode, false);
        harness.awaitFrames(2);
    }

    /** Shift held down around a tap of Tab. */
    private static void shiftTab(int shiftCode) throws Exception {
        key(shiftCode, true);
        harness.awaitFrames(1);
        tap(KeyInput.KEY_TAB);
        key(shiftCode, false);
        harness.awaitFrames(1);
    }

    /**
     * Queue a key event in jME's input manager, as its key input does during the input
     * manager's update (the only time it accepts one); the next frame's update handles it.
     */
    private static void key(int keyCode, boolean pressed) throws Exception {
        harness.call(() -> {
            InputManager input = harness.app().getInputManager();
            Field permitted = InputManager.class.getDeclaredField("eventsPermitted");
            permitted.setAccessible(true);
            permitted.setBoolean(input, true);
            try {
                input.onKeyEvent(new KeyInputEvent(keyCode, '\0', pressed, false));
            } finally {
                permitted.setBoolean(input, false);
            }
            return true;
        });
    }

    private static int selectedNumber() throws Exception {
        return harness.call(() -> demos().indexOf(harness.app().getSwitcher().getSelected())) + 1;
    }

    private static int digitKey(int digit) {
        return digit == 0 ? KeyInput.KEY_0 : KeyInput.KEY_1 + digit - 1;
    }

    /** Every rectangle and number of a demo's layout, exactly, as text to compare. */
    private static String describe(DemoState demo) {
        HudLayout layout = demo.getWindow().getHud().getLayout();
        List<String> parts = new ArrayList<>();
        for (ScreenRect rect : new ScreenRect[] {layout.getWindow(), layout.getTitle(),
            layout.getBody(), layout.getWarning(), layout.getFooter(), layout.getScene(),
            layout.getSidePanel(), layout.getGraph(), layout.getHelpPanel()}) {
            parts.add(rect.getX() + "," + rect.getY() + "," + rect.getWidth() + ","
                    + rect.getHeight());
        }
        PlaneView plane = demo.getWindow().getPlaneView();
        parts.add("scale " + layout.getScale() + ", body lines " + layout.getBodyLines()
                + ", help " + layout.getHelpSize() + ", " + plane.getPixelsPerMetre()
                + " px/m at " + plane.getCentreX() + ", " + plane.getCentreY());
        parts.add(demo.getWindow().getHud().getFooterText());
        // The HUD is rebuilt every frame, so a line of wall-clock figures (the fountain's
        // "physics ... ms/frame ... fps") differs from frame to frame: its text is left out,
        // the lines it took are kept.
        for (String line : demo.getWindow().getHud().getBodyText().split("\n", -1)) {
            parts.add(line.contains(" ms/frame") ? "(measured line)" : line);
        }
        return String.join("\n", parts);
    }

    /**
     * Issue 36: a second application in this JVM (the C key's check once started one) set
     * Lemur up for itself; Lemur keeps one set of globals per JVM, so the window's were
     * replaced by a headless set without input or focus, and the window's next click on the
     * panel threw on the render thread (the second click closed it). An application now gives
     * back the globals it found when it ends, and the C key's check makes no application.
     */
    @Test
    void aSecondApplicationAndTheKeyCLeaveTheWindowItsLemurGlobals() throws Exception {
        DemoState uniform = DemoCatalog.entries().get(DemoCatalog.indexOf("uniform"))
                .create();
        try (HeadlessHarness harness = HeadlessHarness.start(List.of(uniform))) {
            GuiGlobals window = harness.call(GuiGlobals::getInstance);
            StateShare share = harness.call(() -> {
                HeadlessHarness.fly(uniform, 10, 1f / 60f);
                return harness.app().getShareKey().share();
            }).get(60L, TimeUnit.SECONDS);
            assertTrue(share.reproduces(), share.stateLine());
            assertSame(window, harness.call(GuiGlobals::getInstance));
            DemoState other = DemoCatalog.entries().get(DemoCatalog.indexOf("drag")).create();
            ParticleLabApp second = new ParticleLabApp(List.of(other), 0, 5, null, 1f / 60f,
                    false);
            second.start(JmeContext.Type.Headless);
            assertTrue(second.awaitFinished(60L), "the second application ran too long");
            assertNull(second.getFailure());
            assertSame(window, harness.call(GuiGlobals::getInstance));
        }
    }
}
