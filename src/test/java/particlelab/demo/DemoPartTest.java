package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.HudLayout;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * The parts a demo adds with {@link DemoState#addPart}: the demo calls each of a part's hooks
 * once, right after its own hook of the same name, the parts in the order added; their
 * parameters, keys and HUD lines come after the demo's. The physics hooks are checked in plain
 * JUnit (no application); the window's hooks ({@code buildViews}, {@code layOut},
 * {@link DemoPart#afterFrame()}, which only a frame with views calls) in a headless
 * application, in {@link DemoPartsHeadlessTest}.
 */
class DemoPartTest {

    private static final float H = 1f / 60f;

    @Test
    void eachHookReachesEveryPartOnceRightAfterTheDemosOwn() {
        List<String> log = new ArrayList<>();
        RecordingDemo demo = new RecordingDemo(log);
        assertEquals(List.of("a.attach", "b.attach"), log);

        log.clear();
        DemoParameters parameters = demo.getParameters();
        assertEquals(List.of("demo.declareParameters", "a.declareParameters",
                "b.declareParameters"), log);
        // the parts' parameters follow the demo's, in the order added
        int own = parameters.indexOf("own");
        assertTrue(own >= 0, "the demo's parameter is declared");
        // every demo's first part is its energy ledger's (issue 32), then those it added
        assertEquals(own + 1, parameters.indexOf(EnergyPart.PARAMETER));
        assertEquals(own + 2, parameters.indexOf("a"));
        assertEquals(own + 3, parameters.indexOf("b"));

        log.clear();
        demo.getWorld();
        assertEquals(List.of("demo.createScene", "a.stateRecord", "b.stateRecord",
                "demo.declareKeys", "a.declareKeys", "b.declareKeys", "demo.declareDraggables",
                "a.declareDraggables", "b.declareDraggables"), log);
        // a part's draggable follows the demo's, in the order added
        List<String> drags = new ArrayList<>();
        for (Draggable draggable : demo.getWindow().getDragControl().getDraggables()) {
            drags.add(draggable.getGestureLabel());
        }
        assertEquals(List.of("drag demo's ball", "drag a's ball"), drags);
        List<String> keys = new ArrayList<>();
        for (KeyBinding binding : demo.getKeys().getBindings()) {
            keys.add(binding.getKeyLabel());
        }
        // the parts' keys follow the demo's, in the order added
        int ownKey = keys.indexOf("J");
        assertTrue(ownKey >= 0, "the demo's key is bound: " + keys);
        assertEquals(List.of("J", "I", "O"), keys.subList(ownKey, Math.min(ownKey + 3,
                keys.size())));

        log.clear();
        demo.restart();
        assertEquals(List.of("demo.onRestart", "a.onRestart", "b.onRestart"), log);

        log.clear();
        demo.getClock().setMode(SimulationClock.Mode.RAW_TPF);
        demo.getRun().advancePhysics(H);
        // raw tpf: one frame is one step
        assertEquals(1, demo.getWorld().getStepCount());
        assertEquals(List.of("demo.beforeStep", "a.beforeStep", "b.beforeStep",
                "demo.afterStep", "a.afterStep", "b.afterStep"), log);

        log.clear();
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertEquals(List.of("demo.writeHudLines", "a.writeHudLines", "b.writeHudLines"), log);
        assertTrue(hud.endsWith("demo's line\na's line\nb's line\n"), hud);

        log.clear();
        Presentation slide = demo.getWindow().formatPresentation();
        assertEquals(List.of("demo.writePresentation", "a.writePresentation",
                "b.writePresentation"), log);
        // the demo wrote the slide's one readout; the parts add their formula lines after it
        assertEquals("demo's readout", slide.getReadout().toString());
        assertEquals("a's formula\nb's formula", slide.getFormulas().toString());
    }

    @Test
    void aPartsStateRecordGoesBackWithAStepBack() {
        RecordingDemo demo = new RecordingDemo(new ArrayList<>());
        demo.getClock().setMode(SimulationClock.Mode.RAW_TPF);
        for (int i = 0; i < 5; ++i) {
            // raw tpf: one frame is one step
            demo.getRun().advancePhysics(H);
        }
        assertEquals(5, demo.first.steps);
        assertTrue(demo.getReplayControls().stepBack(), "the ring holds the earlier steps");
        // the part's count is read back from the ring with the world's state: exact ints
        assertEquals(4, demo.first.steps);
        demo.getReplayControls().stepForward();
        assertEquals(5, demo.first.steps);
    }

    /** Without a window no part builds views: only a window calls buildViews. */
    @Test
    void noViewsAreBuiltWithoutAWindow() {
        List<String> log = new ArrayList<>();
        RecordingDemo demo = new RecordingDemo(log);
        demo.getRun().advancePhysics(H);
        assertFalse(log.contains("demo.buildViews"), "views built without a window: " + log);
        assertFalse(log.contains("a.buildViews") || log.contains("b.buildViews"), log.toString());
    }

    @Test
    void aPartComesBeforeTheParametersAndTheScene() {
        RecordingDemo demo = new RecordingDemo(new ArrayList<>());
        assertThrows(IllegalArgumentException.class, () -> demo.addPart(null));
        assertThrows(IllegalArgumentException.class, () -> demo.addPart(demo.first));
        demo.getParameters();
        assertThrows(IllegalStateException.class,
                () -> demo.addPart(new RecordingPart("c", KeyInput.KEY_P, "P", demo.log)));
    }

    /** A demo with one particle, one parameter and one key, whose hooks note each call. */
    /** A demo with two parts, a and b, that log every hook they are called at. */
    static final class RecordingDemo extends DemoState {
        private final List<String> log;
        private final RecordingPart first;

        RecordingDemo(List<String> log) {
            super("Recording parts (test)");
            this.log = log;
            first = addPart(new RecordingPart("a", KeyInput.KEY_I, "I", log));
            addPart(new RecordingPart("b", KeyInput.KEY_O, "O", log));
        }

        @Override
        protected void createScene() {
            log.add("demo.createScene");
            addParticle("ball", ColorRGBA.White, Vector3f.ZERO, new Vector3f(1f, 1f, 0f), 1f,
                    new ParticleIntegrator());
        }

        @Override
        protected void declareParameters() {
            log.add("demo.declareParameters");
            declareParameter(new DemoParameter("own", "own value", "m", 0f, 1f, 0.1f, 0.5f, 1,
                    DemoParameter.Applies.LIVE, value -> { }));
        }

        @Override
        protected void declareKeys() {
            log.add("demo.declareKeys");
            bindKey(KeyInput.KEY_J, "J", "the demo's own key", () -> { });
        }

        @Override
        protected void beforeStep(float stepSeconds) {
            log.add("demo.beforeStep");
        }

        @Override
        protected void afterStep(float stepSeconds) {
            log.add("demo.afterStep");
        }

        @Override
        protected void onRestart() {
            log.add("demo.onRestart");
        }

        @Override
        protected void afterFrame() {
            log.add("demo.afterFrame");
        }

        @Override
        protected void buildViews(Application app) {
            log.add("demo.buildViews");
        }

        @Override
        protected void declareDraggables() {
            log.add("demo.declareDraggables");
            declareDraggable(Draggable.launchPosition("demo's ball", getParticles()));
        }

        @Override
        protected void writePresentation(Presentation slide) {
            log.add("demo.writePresentation");
            slide.readout().append("demo's readout");
        }

        @Override
        protected void writeHudLines(StringBuilder text) {
            log.add("demo.writeHudLines");
            text.append("demo's line\n");
        }
    }

    /** A part that declares a parameter and a key named after it and notes each hook. */
    private static final class RecordingPart implements DemoPart {
        private final String name;
        private final int keyCode;
        private final String keyLabel;
        private final List<String> log;
        private DemoState demo;
        /** The steps the part saw: state of its own, recorded in the ring. */
        private int steps;

        RecordingPart(String name, int keyCode, String keyLabel, List<String> log) {
            this.name = name;
            this.keyCode = keyCode;
            this.keyLabel = keyLabel;
            this.log = log;
        }

        @Override
        public void attach(DemoState owner) {
            demo = owner;
            log.add(name + ".attach");
        }

        @Override
        public void declareParameters(DemoParameters parameters) {
            log.add(name + ".declareParameters");
            parameters.add(new DemoParameter(name, name + "'s value", "m", 0f, 1f, 0.1f, 0.5f, 1,
                    DemoParameter.Applies.LIVE, value -> { }));
        }

        @Override
        public void declareKeys() {
            log.add(name + ".declareKeys");
            demo.bindKey(keyCode, keyLabel, name + "'s key", () -> { });
        }

        @Override
        public void beforeStep(float stepSeconds) {
            log.add(name + ".beforeStep");
        }

        @Override
        public void afterStep(float stepSeconds) {
            log.add(name + ".afterStep");
            ++steps;
        }

        @Override
        public StateRecord stateRecord() {
            log.add(name + ".stateRecord");
            return new StateRecord() {
                @Override
                public int countStateInts() {
                    return 1;
                }

                @Override
                public void writeState(StateSlab slab) {
                    slab.putInt(steps);
                }

                @Override
                public void readState(StateSlab slab) {
                    steps = slab.getInt();
                }
            };
        }

        @Override
        public void declareDraggables() {
            log.add(name + ".declareDraggables");
            if (name.equals("a")) {
                demo.declareDraggable(Draggable.launchPosition("a's ball",
                        demo.getParticles()));
            }
        }

        @Override
        public void layOut(HudLayout layout) {
            log.add(name + ".layOut");
        }

        @Override
        public void writePresentation(Presentation slide) {
            log.add(name + ".writePresentation");
            slide.formula().append(name).append("'s formula");
        }

        @Override
        public void onRestart() {
            log.add(name + ".onRestart");
        }

        @Override
        public void afterFrame() {
            log.add(name + ".afterFrame");
        }

        @Override
        public void buildViews(Application app) {
            log.add(name + ".buildViews");
        }

        @Override
        public void writeHudLines(StringBuilder text) {
            log.add(name + ".writeHudLines");
            text.append(name).append("'s line\n");
        }
    }
}
