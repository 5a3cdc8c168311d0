package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.font.BitmapFont;
import com.jme3.input.KeyInput;
import com.jme3.scene.Node;
import java.util.List;
import particlelab.physics.SimulationClock;
import particlelab.view.HudLayout;
import particlelab.view.ParameterPanel;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;

/**
 * What {@link DemoState} does with a demo's parameters, in one place: declares the shared
 * one (the fixed step h), the panel's keys, builds the panel (Lemur) in the HUD's side panel
 * slot, applies waiting values at each launch, and keeps the last shots. The demo state calls
 * it through a few lines.
 */
final class ParameterControls {

    /** The fixed step h's range (in seconds): from 1/240 to 1/5 s. */
    static final float MIN_STEP_SECONDS = 1f / 240f;
    static final float MAX_STEP_SECONDS = 1f / 5f;
    /** The steps the panel's keys and slider go through (in seconds). */
    private static final float[] STEP_STOPS = {1f / 240f, 1f / 120f, 1f / 90f, 1f / 60f,
        1f / 45f, 1f / 30f, 1f / 20f, 1f / 15f, 1f / 10f, 1f / 5f};

    private final DemoParameters parameters;
    private final StringBuilder legend = new StringBuilder(512);
    private KeptShots keptShots;
    private ParameterPanel panel;
    /**
     * Hidden at the start (F2 shows it): the side panel narrows the scene, and at some
     * window sizes the labels of drag's and thrust's spheres then find no slot clear of the
     * trails.
     */
    private boolean panelVisible;
    private boolean legendDirty = true;
    /** The parameters' version the legend was written for. */
    private int legendVersion = Integer.MIN_VALUE;
    /** The demo's recorded steps, shown and scrubbed by the timeline (null: no timeline). */
    private Replay replay;
    /** The timeline's text, rebuilt only when what it says changed. */
    private final StringBuilder timelineText = new StringBuilder(128);
    private final StringBuilder timelineScratch = new StringBuilder(128);

    /**
     * Create the panel's controls of a demo's parameters.
     *
     * @param parameters the demo's parameters, whose values its run owns (not null)
     */
    ParameterControls(DemoParameters parameters) {
        this.parameters = parameters;
    }

    /**
     * Access the parameters.
     *
     * @return the live parameters (not null)
     */
    DemoParameters getParameters() {
        return parameters;
    }

    /**
     * Declare the parameters every demo has: the fixed step h, applied live (the T key
     * switches to raw tpf, which ignores it).
     *
     * @param applyStep puts a new h into the clock and tells the demo (not null)
     */
    void declareShared(DemoParameter.Setter applyStep) {
        parameters.add(new DemoParameter("h", "fixed step", "s",
                MIN_STEP_SECONDS, MAX_STEP_SECONDS, MIN_STEP_SECONDS,
                SimulationClock.DEFAULT_STEP_SECONDS, 4, DemoParameter.Applies.LIVE,
                applyStep)
                .withStops(STEP_STOPS).withDisplay(DemoParameter::appendStep));
    }

    /**
     * Declare the panel's keys: select a line, change its value, show or hide the panel,
     * clear the kept shots.
     *
     * @param keys the demo's keys (not null, modified)
     * @param relayOut lays the HUD and the scene out again, after the panel came or went
     *     (not null)
     */
    void declareKeys(DemoKeys keys, Runnable relayOut) {
        keys.addShared(new KeyBinding(new int[] {KeyInput.KEY_LBRACKET, KeyInput.KEY_RBRACKET},
                new String[] {"[", "]"}, "parameter panel: select the line above / below",
                null, key -> parameters.moveSelection(key == 0 ? -1 : 1)));
        keys.addShared(new KeyBinding(new int[] {KeyInput.KEY_COMMA, KeyInput.KEY_PERIOD},
                new String[] {",", "."}, "parameter panel: value down / up (launch values:"
                        + " from the next launch)",
                null, key -> parameters.nudgeSelected(key == 0 ? -1 : 1)));
        keys.addShared(new KeyBinding(KeyInput.KEY_F2, "F2",
                "show / hide the parameter panel (mouse: sliders and buttons)", () -> {
                    panelVisible = !panelVisible;
                    relayOut.run();
                }));
        keys.addShared(new KeyBinding(KeyInput.KEY_BACK, "Backspace",
                "clear the kept shots (the faint paths of the last launches)",
                this::clearShots));
    }

    /**
     * Build the panel and the kept shots' paths, and ask the HUD for the side panel slot.
     * Call once, after the scene's views were built.
     *
     * @param app the application (not null)
     * @param font the HUD's font (not null)
     * @param layout the HUD's layout (not null, modified: the panel's width)
     * @param particles the demo's particles (not null, live)
     * @param scene the scene holding their views, built (not null)
     * @param radiusMetres the particles' drawn radius (in metres, &gt;0)
     * @param sceneNode where the kept paths go (not null, modified)
     * @param labels the buttons' texts (not null)
     * @param actions what each button does (not null, one per label)
     */
    void build(Application app, BitmapFont font, HudLayout layout,
            List<DemoParticle> particles, DemoScene scene, float radiusMetres,
            Node sceneNode, List<String> labels, List<Runnable> actions) {
        keptShots = new KeptShots(parameters.size());
        keptShots.build(app.getAssetManager(), particles, scene, radiusMetres, sceneNode);
        keptShots.launched(parameters);
        panel = new ParameterPanel(parameters, font, "Parameters  (F2 hides)", labels,
                actions);
        if (replay != null) {
            panel.addTimeline();
        }
        layout.setPanelWidth(panelVisible ? ParameterPanel.WIDTH_AT_SCALE_ONE : 0f);
    }

    /**
     * Return the record of how many shots are kept, for the replay ring: a step back shows
     * the kept paths of that step.
     *
     * @return a new record (not null)
     */
    StateRecord keptShotsRecord() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putInt(countKeptShots());
            }

            @Override
            public void readState(StateSlab slab) {
                showKeptShotsUpTo(slab.getInt());
            }
        };
    }

    /**
     * Give the panel a timeline over the demo's recorded steps. Call before {@link #build}.
     *
     * @param newReplay the demo's replay (not null)
     */
    void setReplay(Replay newReplay) {
        replay = newReplay;
    }

    /**
     * Ask the HUD for the panel's slot, or none while the panel is hidden. Call before the
     * HUD is laid out again.
     *
     * @param layout the HUD's layout (not null, modified)
     */
    void requestSlot(HudLayout layout) {
        layout.setPanelWidth(panelVisible ? ParameterPanel.WIDTH_AT_SCALE_ONE : 0f);
    }

    /** @return true while the panel is shown */
    boolean isPanelVisible() {
        return panelVisible;
    }

    /**
     * Access the panel.
     *
     * @return the live panel (null before {@link #build})
     */
    ParameterPanel getPanel() {
        return panel;
    }

    /**
     * Access the kept shots.
     *
     * @return the live store (null before {@link #build})
     */
    KeptShots getKeptShots() {
        return keptShots;
    }

    /**
     * Count the shots kept since the demo started, for the recorded state.
     *
     * @return the count (&ge;0; 0 before {@link #build})
     */
    int countKeptShots() {
        return keptShots == null ? 0 : keptShots.countKept();
    }

    /**
     * Show the kept shots as a recorded state had them (a step back or forward), the legend
     * too. Allocates nothing.
     *
     * @param keptThen {@link #countKeptShots()} in that state (&ge;0)
     */
    void showKeptShotsUpTo(int keptThen) {
        if (keptShots != null) {
            int before = keptShots.size();
            keptShots.showUpTo(keptThen);
            legendDirty |= before != keptShots.size();
        }
    }

    /**
     * Before a launch or a reset puts the particles at their launch states: keep the shot
     * that ends, then apply the values that waited for the launch. Allocates nothing.
     */
    void beforeLaunch() {
        if (keptShots != null) {
            keptShots.keep();
            legendDirty = true;
        }
        parameters.applyPending();
        if (keptShots != null) {
            keptShots.launched(parameters);
        }
    }

    /**
     * Follow the mouse and the keys, and put the panel in its slot: once a frame, after the
     * HUD was laid out. Allocates nothing while nothing changed.
     *
     * @param layout the HUD's layout (not null, not modified)
     */
    void update(HudLayout layout) {
        if (panel == null) {
            return;
        }
        if (legendDirty || legendVersion != parameters.getVersion()) {
            legendDirty = false;
            legendVersion = parameters.getVersion();
            legend.setLength(0);
            keptShots.formatLegend(legend, parameters);
            panel.setLegend(legend);
        }
        updateTimeline();
        // the texts first, so the panel is placed (and wrapped) with this frame's texts
        panel.refresh();
        panel.place(layout.getSidePanel(), layout.getPanelScale());
    }

    /**
     * The timeline: a move of its slider shows that recorded step (pausing); otherwise it
     * follows the step shown. While the clock runs at the live end it says so and stays at
     * the right end, so its text (a Lemur label, rewritten only on change) stays the same.
     */
    private void updateTimeline() {
        if (replay == null) {
            return;
        }
        double moved = panel.takeTimelineMove();
        if (!Double.isNaN(moved)) {
            replay.scrub(moved);
        }
        StateRing ring = replay.getRing();
        timelineScratch.setLength(0);
        if (replay.isBehind() || replay.isPaused()) {
            timelineScratch.append("timeline: step ")
                    .append(replay.getShownIndex() - ring.getFirstIndex()).append(" of ")
                    .append(Math.max(0, ring.size() - 1)).append(", t = ");
            TextFormat.appendFixed(timelineScratch, replay.getShownSeconds(), 2)
                    .append(" s\n");
        } else {
            timelineScratch.append("timeline: live, Home steps back\n");
        }
        replay.appendRing(timelineScratch);
        if (!TextFormat.sameText(timelineText, timelineScratch)) {
            timelineText.setLength(0);
            timelineText.append(timelineScratch);
        }
        panel.setTimeline(timelineText, replay.getFraction());
    }

    /** @return how many kept shots are held to be drawn (0 before {@link #build}) */
    int countHeldShots() {
        return keptShots == null ? 0 : keptShots.countHeld();
    }

    /** Forget the kept shots and their legend (before {@link #build}, nothing). */
    void clearShots() {
        if (keptShots != null) {
            keptShots.clear();
            legendDirty = true;
        }
    }
}
