package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.KeyInput;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.view.HudLayout;

/**
 * The window's controls in a real headless application: a reshape (the camera resized, as
 * jME does on every window resize) and a new HUD factor lay the shown demo out again on the
 * next frame; the keys are in every demo's help; fullscreen without a window says so; F8's
 * presentation mode stays on across demos and tour stops.
 */
class WindowControlsHeadlessTest {

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
        assertEquals(1920f, harness.call(() -> demo.getHud().getLayout().getWindow()
                .getWidth()));
        assertEquals(HudLayout.scaleFor(1920, 1080),
                harness.call(() -> demo.getHud().getLayout().getScale()));

        harness.call(() -> {
            app.getWindowControls().setUiFactor(0.5f);
            return true;
        });
        harness.awaitFrames(2);
        assertTrue(harness.call(() -> demo.getDemoHud().isLaidOutFor(1920, 1080, 0.5f)));
        assertEquals(0.5f * HudLayout.scaleFor(1920, 1080),
                harness.call(() -> demo.getHud().getLayout().getScale()));

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
                harness.call(() -> app.getSwitcher().getSelected().getNotice()));
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
            assertTrue(harness.call(() -> switcher.getSelected().getHud().getLayout()
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
            assertTrue(harness.call(() -> switcher.getSelected().getHud().getFooterText()
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

    private static KeyBinding find(ParticleLabApp app, int keyCode) {
        for (KeyBinding binding : app.getSwitcher().getBindings()) {
            if (binding.getKeyCode(0) == keyCode) {
                return binding;
            }
        }
        throw new IllegalStateException("no application key " + keyCode);
    }
}
