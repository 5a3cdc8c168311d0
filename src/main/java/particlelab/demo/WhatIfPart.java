package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.function.Supplier;
import particlelab.view.Trail;

/**
 * What-if forks on screen (issue 33): from the step shown (live, or stepped back with Home,
 * End or the timeline) Insert forks a lane that runs the demo's own code on from that state
 * with one change ({@link WhatIfFork}); up to {@link #MAX_LANES} lanes, each with its own
 * change, draw their paths in ghost colours beside the demo's, so the futures part before
 * the class's eyes. Delete chooses the change the next fork gets, from the demo's list;
 * J keeps the newest lane: the demo goes on from the forked step with its change, ending in
 * the lane's state bit for bit. Insert with every lane taken drops the lanes.
 *
 * <p>The lanes run on their own: each frame every lane's time goes on by
 * {@link #LANE_SECONDS_PER_FRAME} and it takes steps of its own h up to the nearest,
 * whether the demo is paused or not, until {@link #MAX_LANE_STEPS} steps or its scene is
 * over. Per frame the part allocates nothing; a fork (a key press) builds its twin and
 * trails once, then reuses them.
 */
public final class WhatIfPart implements DemoPart {

    /** The most lanes forked at once. */
    static final int MAX_LANES = 3;
    /** Simulated time each lane goes on by per frame (in seconds): real time at 60 Hz. */
    static final double LANE_SECONDS_PER_FRAME = 1.0 / 60.0;
    /** The most steps a lane takes, and the points its trails hold. */
    static final int MAX_LANE_STEPS = 900;
    /** The most particles of a lane drawn (each with a trail). */
    private static final int MAX_TRAILS_PER_LANE = 4;
    /** The most steps a lane takes in one frame (a small h at a frame's time). */
    private static final int MAX_STEPS_PER_FRAME = 16;
    /** The trails' width (in metres). */
    private static final float TRAIL_WIDTH_METRES = 0.06f;
    /** The lanes' ghost colours, and their names for the HUD. */
    private static final ColorRGBA[] COLORS = {new ColorRGBA(1f, 0.45f, 0.9f, 1f),
        new ColorRGBA(1f, 1f, 0.3f, 1f), new ColorRGBA(0.6f, 0.6f, 1f, 1f)};
    private static final String[] COLOR_NAMES = {"pink", "yellow", "lilac"};

    private final Supplier<DemoState> twins;
    /**
     * How far each lane's paths are drawn to the right of the one before (in metres): 0 in
     * the flights, whose paths part in the plane; a bounce falls on one vertical line.
     */
    private final float laneOffsetMetres;
    /** Scratch: a point of a lane, moved beside the others. */
    private final Vector3f drawnPoint = new Vector3f();
    /** The changes offered, by parameter name (null: nothing changed, the recorded future). */
    private final String[] changeNames;
    private final float[] changeValues;
    private final WhatIfFork[] lanes = new WhatIfFork[MAX_LANES];
    private final Trail[][] trails = new Trail[MAX_LANES][];
    /** The simulated time each lane has reached, since its fork (in seconds). */
    private final double[] laneSeconds = new double[MAX_LANES];
    private DemoState demo;
    private Material material;
    private int laneCount;
    /** The change the next fork gets: an index into the list. */
    private int offered;
    private KeyBinding forkKey;

    /**
     * Create the forks of a demo.
     *
     * @param twins makes a new instance of the demo's class, for a fork (not null)
     * @param changeNames the changes offered, by {@code --set} name; null for none, the
     *     recorded future (not null, not empty)
     * @param changeValues each change's value (same length)
     * @param laneOffsetMetres how far each lane is drawn right of the one before (in
     *     metres, finite, &ge;0)
     */
    public WhatIfPart(Supplier<DemoState> twins, String[] changeNames, float[] changeValues,
            float laneOffsetMetres) {
        if (twins == null || changeNames == null || changeValues == null
                || changeNames.length == 0 || changeNames.length != changeValues.length) {
            throw new IllegalArgumentException("what-if changes must be one value per name,"
                    + " at least one, and a twin factory");
        }
        this.twins = twins;
        this.changeNames = changeNames.clone();
        this.changeValues = changeValues.clone();
        if (!(laneOffsetMetres >= 0f) || Float.isInfinite(laneOffsetMetres)) {
            throw new IllegalArgumentException("what-if lane offset (m) must be finite and"
                    + " >= 0, but was " + laneOffsetMetres);
        }
        this.laneOffsetMetres = laneOffsetMetres;
    }

    @Override
    public void attach(DemoState owner) {
        demo = owner;
    }

    @Override
    public void declareKeys() {
        // One help row for the three (the help stays legible at 1280x720): Insert forks a
        // lane (up to MAX_LANES; once more drops them), Delete offers the next change, J
        // keeps the newest lane (the run goes on from it, with its change).
        forkKey = demo.getKeys().bindKeys(new KeyBinding(
                new int[] {KeyInput.KEY_INSERT, KeyInput.KEY_DELETE, KeyInput.KEY_J},
                new String[] {"Insert", "Delete", "J"},
                "what if: fork a lane, next change, keep the newest", null, key -> {
                            if (key == 0) {
                                forkOrDrop();
                            } else if (key == 1) {
                                offered = (offered + 1) % changeNames.length;
                            } else {
                                keepNewest();
                            }
                        }).withKeyLabel("Ins/Del/J"));
    }

    @Override
    public void buildViews(Application app) {
        material = new Material(app.getAssetManager(), "Common/MatDefs/Misc/Unshaded.j3md");
    }

    /** Once a frame: every lane goes on by its share of time, its trails follow. */
    @Override
    public void afterFrame() {
        for (int lane = 0; lane < laneCount; ++lane) {
            WhatIfFork fork = lanes[lane];
            DemoRun run = fork.getRun();
            laneSeconds[lane] += LANE_SECONDS_PER_FRAME;
            float h = run.getClock().getStepSeconds();
            int taken = 0;
            // Steps while the lane's time is nearer the next step's end than this one's: a
            // float h such as 1/60 s is a little over, and must not lose a step.
            while ((fork.getSteps() + 0.5) * h <= laneSeconds[lane]
                    && fork.getSteps() < MAX_LANE_STEPS && taken < MAX_STEPS_PER_FRAME
                    && !run.isSceneOver()) {
                fork.step();
                ++taken;
                addTrailPoints(lane);
            }
            refreshTrails(lane);
        }
    }

    @Override
    public void onRestart() {
        dropLanes();
    }

    /** While lanes are shown: one line naming each lane's colour and change. */
    @Override
    public void writeHudLines(StringBuilder text) {
        if (laneCount == 0) {
            return;
        }
        text.append("what if (J keeps the newest, Insert ");
        text.append(laneCount < MAX_LANES ? "forks another" : "drops them").append("):");
        for (int lane = 0; lane < laneCount; ++lane) {
            text.append(lane == 0 ? "  " : ",  ").append(COLOR_NAMES[lane]).append(' ');
            appendChange(text, lanes[lane].getParameter(), lanes[lane].getValue());
        }
        text.append(";  next: ");
        appendChange(text, changeNames[offered], changeValues[offered]).append('\n');
    }

    /** @return how many lanes are forked (0 to {@link #MAX_LANES}) */
    int countLanes() {
        return laneCount;
    }

    /**
     * Access a lane.
     *
     * @param lane which (&ge;0, &lt;{@link #countLanes()})
     * @return the fork (live, not null)
     */
    WhatIfFork getLane(int lane) {
        return lanes[lane];
    }

    /** @return the Insert binding (for the help and tests) */
    KeyBinding getForkKey() {
        return forkKey;
    }

    /** Insert: fork a lane with the change offered, or drop the lanes when all are taken. */
    void forkOrDrop() {
        if (laneCount == MAX_LANES) {
            dropLanes();
            return;
        }
        int lane = laneCount;
        if (lanes[lane] == null) {
            lanes[lane] = new WhatIfFork(twins.get());
        }
        DemoRun run = demo.getRun();
        run.getClock().setPaused(true);
        if (run.getStateRing().size() == 0) {
            // Nothing recorded yet (before the first step): record the launch to fork from.
            run.getReplay().beforeStep();
        }
        lanes[lane].start(demo, run.getShownStep(), changeNames[offered],
                changeValues[offered]);
        laneSeconds[lane] = 0.0;
        laneCount = lane + 1;
        prepareTrails(lane);
        addTrailPoints(lane);
        offered = (offered + 1) % changeNames.length;
    }

    /** J: keep the newest lane, then drop the lanes (their futures are no longer shown). */
    void keepNewest() {
        if (laneCount == 0) {
            return;
        }
        WhatIfFork kept = lanes[laneCount - 1];
        dropLanes();
        kept.keep(demo);
    }

    private void dropLanes() {
        for (int lane = 0; lane < laneCount; ++lane) {
            if (trails[lane] != null) {
                for (Trail trail : trails[lane]) {
                    trail.clear();
                    trail.getGeometry().removeFromParent();
                    trail.getDotGeometry().removeFromParent();
                }
            }
        }
        laneCount = 0;
    }

    /** Build a lane's trails once (a key press), attach them. */
    private void prepareTrails(int lane) {
        if (material == null) {
            return;
        }
        int count = Math.min(MAX_TRAILS_PER_LANE, lanes[lane].getRun().getParticles().size());
        if (trails[lane] == null || trails[lane].length != count) {
            trails[lane] = new Trail[count];
            for (int i = 0; i < count; ++i) {
                trails[lane][i] = new Trail("what-if " + COLOR_NAMES[lane] + " " + i,
                        MAX_LANE_STEPS + 1, TRAIL_WIDTH_METRES, COLORS[lane], material);
            }
        }
        for (Trail trail : trails[lane]) {
            trail.clear();
            trail.setDotsVisible(false);
            demo.getSceneNode().attachChild(trail.getGeometry());
            demo.getSceneNode().attachChild(trail.getDotGeometry());
        }
    }

    private void addTrailPoints(int lane) {
        Trail[] laneTrails = trails[lane];
        if (laneTrails == null) {
            return;
        }
        for (int i = 0; i < laneTrails.length; ++i) {
            drawnPoint.set(lanes[lane].getRun().getParticles().get(i).getParticle().position);
            drawnPoint.x += laneOffsetMetres * (lane + 1);
            laneTrails[i].add(drawnPoint);
        }
    }

    private void refreshTrails(int lane) {
        Trail[] laneTrails = trails[lane];
        if (laneTrails == null) {
            return;
        }
        for (int i = 0; i < laneTrails.length; ++i) {
            laneTrails[i].refresh();
        }
    }

    /** "h = 1/30 s", "e = 0.6", "method = euler" (a choice by its name), "as recorded". */
    private StringBuilder appendChange(StringBuilder text, String name, float value) {
        if (name == null) {
            return text.append("as recorded");
        }
        text.append(name).append(" = ");
        if ("h".equals(name)) {
            return DemoParameter.appendStep(text, value);
        }
        DemoParameters parameters = demo.getParameters();
        int index = parameters.indexOf(name);
        if (index >= 0 && parameters.get(index).isChoice()) {
            return text.append(parameters.get(index).getChoice(Math.round(value)));
        }
        return DemoParameter.appendShort(text, value, 2);
    }
}
