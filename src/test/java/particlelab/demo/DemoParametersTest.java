package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The declarations and their values, without jME: ranges, LIVE against NEXT_LAUNCH, the
 * panel's keys and slider, the texts.
 */
class DemoParametersTest {

    /** What the setters received, in order: the last value of each. */
    private final float[] applied = {Float.NaN, Float.NaN};
    private final int[] calls = new int[2];

    private DemoParameters twoParameters() {
        DemoParameters parameters = new DemoParameters();
        parameters.add(new DemoParameter("b", "linear drag", "N s/m", 0f, 5f, 0.05f, 0.9f, 2,
                DemoParameter.Applies.LIVE, value -> record(0, value)));
        parameters.add(new DemoParameter("speed", "launch speed", "m/s", 0.5f, 30f, 0.5f,
                14f, 2, DemoParameter.Applies.NEXT_LAUNCH, value -> record(1, value)));
        return parameters;
    }

    private void record(int which, float value) {
        applied[which] = value;
        ++calls[which];
    }

    @Test
    void outOfRangeValueIsRefusedWithTheRange() {
        DemoParameters parameters = twoParameters();
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> parameters.set("b", 7f));
        assertTrue(refused.getMessage().contains("b = 7.0 is out of range"),
                refused.getMessage());
        assertTrue(refused.getMessage().contains("b (linear drag) from 0.00 N s/m to 5.00"
                + " N s/m"), refused.getMessage());
        // ... and the other parameter's range too, so the user sees every choice.
        assertTrue(refused.getMessage().contains("speed (launch speed) from 0.50 m/s to"
                + " 30.00 m/s"), refused.getMessage());
        IllegalArgumentException nan = assertThrows(IllegalArgumentException.class,
                () -> parameters.set(0, Float.NaN));
        assertTrue(nan.getMessage().contains("b = NaN"), nan.getMessage());
        assertEquals(0.9f, parameters.getValue("b"));
    }

    @Test
    void unknownNameIsRefusedListingTheParameters() {
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> twoParameters().set("q", 1f));
        assertTrue(refused.getMessage().startsWith("no parameter named \"q\"; the parameters"
                + " are b (linear drag) from 0.00 N s/m to 5.00 N s/m, speed"),
                refused.getMessage());
    }

    @Test
    void declarationsAreChecked() {
        DemoParameters parameters = twoParameters();
        assertThrows(IllegalArgumentException.class, () -> parameters.add(new DemoParameter(
                "b", "again", "", 0f, 1f, 0.1f, 0.5f, 1, DemoParameter.Applies.LIVE,
                value -> { })));
        assertThrows(IllegalArgumentException.class, () -> new DemoParameter("B", "upper",
                "", 0f, 1f, 0.1f, 0.5f, 1, DemoParameter.Applies.LIVE, value -> { }));
        assertThrows(IllegalArgumentException.class, () -> new DemoParameter("x", "default",
                "", 0f, 1f, 0.1f, 2f, 1, DemoParameter.Applies.LIVE, value -> { }));
        assertThrows(IllegalArgumentException.class, () -> new DemoParameter("x", "range",
                "", 1f, 1f, 0.1f, 1f, 1, DemoParameter.Applies.LIVE, value -> { }));
    }

    @Test
    void nothingReachesTheSceneBeforeStartThenEveryValueDoes() {
        DemoParameters parameters = twoParameters();
        parameters.set("b", 0.3f);
        parameters.set("speed", 20f);
        assertEquals(0, calls[0] + calls[1]);
        parameters.start();
        assertEquals(0.3f, applied[0]);
        assertEquals(20f, applied[1]);
        assertFalse(parameters.isPending(1));
    }

    @Test
    void liveChangeAppliesAtOnceAndLaunchChangeWaitsForTheLaunch() {
        DemoParameters parameters = twoParameters();
        parameters.start();
        parameters.set("b", 0.3f);
        assertEquals(0.3f, applied[0]);
        assertEquals(0.3f, parameters.getValueInScene(0));
        parameters.set("speed", 20f);
        assertEquals(14f, applied[1]);
        assertTrue(parameters.isPending(1));
        assertEquals(14f, parameters.getValueInScene(1));
        parameters.applyPending();
        assertEquals(20f, applied[1]);
        assertFalse(parameters.isPending(1));
        int before = calls[0] + calls[1];
        parameters.applyPending();
        assertEquals(before, calls[0] + calls[1], "nothing waits: nothing is applied again");
    }

    @Test
    void keysSelectWrapAroundAndNudgeWithinTheRange() {
        DemoParameters parameters = twoParameters();
        parameters.start();
        parameters.moveSelection(-1);
        assertEquals(1, parameters.getSelected());
        parameters.moveSelection(1);
        assertEquals(0, parameters.getSelected());
        parameters.nudgeSelected(1);
        // 0.9 + 0.05, rounded to whole steps from 0: 19 steps of 0.05 (float round-off).
        assertEquals(0.95f, parameters.getValue(0), 1e-6f);
        for (int i = 0; i < 200; ++i) {
            parameters.nudgeSelected(-1);
        }
        assertEquals(0f, parameters.getValue(0));
    }

    @Test
    void stepStopsAndTheirDisplay() {
        ParameterControls controls = new ParameterControls(new DemoParameters());
        controls.declareShared(new particlelab.physics.SimulationClock()::setStepSeconds);
        DemoParameter h = controls.getParameters().get(0);
        assertEquals("h", h.getName());
        assertEquals(1f / 60f, h.getDefault());
        assertEquals(1f / 45f, h.nudged(1f / 60f, 1));
        assertEquals(1f / 90f, h.nudged(1f / 60f, -1));
        assertEquals(1f / 5f, h.nudged(1f / 5f, 1));
        assertEquals(1f / 240f, h.nudged(1f / 240f, -1));
        assertEquals(1f / 240f, h.valueAtFraction(0f));
        assertEquals(1f / 5f, h.valueAtFraction(1f));
        assertEquals("1/60 s", h.appendValue(new StringBuilder(), 1f / 60f).toString());
        assertEquals("0.0123 s", h.appendValue(new StringBuilder(), 0.0123f).toString());
        assertEquals("h (fixed step) from 1/240 s to 1/5 s", h.toString());
    }

    @Test
    void panelRowsAndDifferencesAreWrittenFromTheDeclarations() {
        DemoParameters parameters = twoParameters();
        parameters.start();
        parameters.set("speed", 20f);
        assertEquals("> b = 0.90 N s/m   linear drag\n"
                + "  speed = 20.00 m/s   launch speed  (next launch)\n",
                parameters.formatPanel(new StringBuilder()).toString());
        float[] then = parameters.copyValuesInScene(new float[2]);
        parameters.set("b", 0.3f);
        parameters.applyPending();
        float[] now = parameters.copyValuesInScene(new float[2]);
        StringBuilder text = new StringBuilder();
        assertEquals(2, parameters.appendDifferences(text, then, now));
        assertEquals("b = 0.90 N s/m vs 0.30 N s/m,  speed = 14.00 m/s vs 20.00 m/s",
                text.toString());
    }

    @Test
    void aChoiceIsSetByIndexShownByNameAndStepsThroughItsNames() {
        DemoParameters parameters = new DemoParameters();
        parameters.add(DemoParameter.choice("preset", "collision preset",
                new String[] {"head-on", "glancing", "cradle"}, 0, DemoParameter.Applies.LIVE,
                value -> record(0, value)));
        DemoParameter preset = parameters.get(0);
        assertTrue(preset.isChoice());
        assertEquals(1, preset.indexOfChoice("glancing"));
        assertEquals(-1, preset.indexOfChoice("Glancing"));
        assertEquals("preset (collision preset) one of head-on|glancing|cradle",
                preset.toString());
        parameters.start();
        parameters.set(0, 2f);
        assertEquals(2f, applied[0]);
        assertEquals("> preset = cradle   collision preset\n",
                parameters.formatPanel(new StringBuilder()).toString());
        // The panel's keys step one name at a time and stop at the ends.
        parameters.nudgeSelected(1);
        assertEquals(2f, parameters.getValue(0));
        parameters.nudgeSelected(-1);
        assertEquals(1f, parameters.getValue(0));
        // Between two names is no value.
        assertFalse(preset.accepts(0.5f));
        assertThrows(IllegalArgumentException.class, () -> parameters.set(0, 0.5f));
        assertEquals(1f, parameters.getValue(0));
    }

    @Test
    void aChoiceNeedsTwoDistinctCommandLineNames() {
        DemoParameter.Setter none = value -> { };
        assertThrows(IllegalArgumentException.class, () -> DemoParameter.choice("mode",
                "mode", new String[] {"only"}, 0, DemoParameter.Applies.LIVE, none));
        assertThrows(IllegalArgumentException.class, () -> DemoParameter.choice("mode",
                "mode", new String[] {"on", "on"}, 0, DemoParameter.Applies.LIVE, none));
        assertThrows(IllegalArgumentException.class, () -> DemoParameter.choice("mode",
                "mode", new String[] {"on", "Off"}, 0, DemoParameter.Applies.LIVE, none));
        assertThrows(IllegalArgumentException.class, () -> DemoParameter.choice("mode",
                "mode", new String[] {"on", "off"}, 2, DemoParameter.Applies.LIVE, none));
    }
}
