package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.math.ColorRGBA;
import particlelab.physics.EnergyLedger;
import particlelab.view.EnergyBars;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.world.World;
import particlelab.world.WorldEnergy;

/**
 * Where the energy goes (issue 32): every demo's part that keeps the {@link WorldEnergy}
 * ledger of its world, records it for the export ({@code energy.csv}, one row per step) and,
 * when shown (the panel's "energy ledger", {@code --set energy=on}), draws it as
 * {@link EnergyBars} in the HUD's ledger strip down the scene's right edge
 * ({@link HudLayout#getLedger}; the scene stays left of it, so no body flies under it) and
 * writes its equation on one HUD line. A bar per column: kinetic, potential, spring, thrust
 * work, drag loss, impact loss, script work, emitted and removed (the fountain's particles
 * that come and go) and the numerical column, the energy the steps themselves created or
 * destroyed, in a colour of its own. Energy held or put in goes right
 * of the zero line, energy taken (drag, impacts) left of it; the scale is a round number at
 * or above the largest energy since the last reset (the start's, at first), so the bars do
 * not jitter from frame to frame.
 *
 * <p>Hidden by default in the full HUD: the strip takes a third of the scene's width. In
 * presentation mode the bars are shown where the slide is about energy
 * ({@link #showOnSlide}: bounce, collisions, clip, spring, racket) or when switched on. A
 * parameter rather than a key: every letter is taken by some demo, and a part's key would
 * sit among each demo's own keys.
 *
 * <p>A demo whose particles are no bodies of its world keeps its own ledger
 * ({@link #useOwnLedger}: the fountain's), kept only while wanted since it costs a pass over
 * its particles a step.
 *
 * <p>The ledger starts at the demo's first step and again at every reset. Its step hooks,
 * frame hook and HUD line allocate nothing.
 */
public final class EnergyPart implements DemoPart {

    /** The parameter's name ({@code --set energy=on}). */
    public static final String PARAMETER = "energy";
    /** The export's table name: {@code energy.csv}. */
    public static final String TABLE_NAME = "energy";
    /** The first bar's name: the start's energy, which the others add up to. */
    private static final String START_NAME = "start";
    private static final ColorRGBA START_COLOR = new ColorRGBA(0.6f, 0.6f, 0.65f, 1f);
    /** The bars' names of the columns, in {@link EnergyLedger#getColumn}'s order. */
    private static final String[] BAR_NAMES = {"kinetic", "potential", "spring",
        "thrust work", "drag loss", "impact loss", "script work", "emitted", "removed",
        "numerical"};
    /** The bars' colours, likewise: the numerical bar's is like none of the others'. */
    private static final ColorRGBA[] BAR_COLORS = {
        new ColorRGBA(0.35f, 0.65f, 1f, 1f),
        new ColorRGBA(0.35f, 0.85f, 0.4f, 1f),
        new ColorRGBA(0.3f, 0.85f, 0.8f, 1f),
        new ColorRGBA(1f, 0.6f, 0.2f, 1f),
        new ColorRGBA(0.95f, 0.3f, 0.3f, 1f),
        new ColorRGBA(0.85f, 0.4f, 0.85f, 1f),
        new ColorRGBA(0.9f, 0.85f, 0.3f, 1f),
        new ColorRGBA(0.75f, 0.95f, 0.35f, 1f),
        new ColorRGBA(0.7f, 0.55f, 0.45f, 1f),
        new ColorRGBA(1f, 1f, 1f, 1f)};
    /** The widest name the strip keeps room for. */
    private static final String WIDEST_NAME = "thrust work";
    /**
     * The bars' text when presenting, as a fraction of the slide's text: read from the back
     * row beside the slide's large type (the full HUD's is the scene labels' size).
     */
    private static final float PRESENT_TEXT_FRACTION = 0.6f;
    /** The bars' rows: the start, every column and the numerical one. */
    private static final int ROWS = EnergyLedger.NUMERICAL_COLUMN + 2;

    private DemoState demo;
    private WorldEnergy energy;
    /** The demo's own ledger, kept only while wanted (null: the world's, {@link #energy}). */
    private OwnLedger own;
    private StepTable table;
    /** The columns {@link #table} was made for. */
    private int tableColumns;
    private boolean shown;
    /** Shown on the slide in presentation mode even when not switched on. */
    private boolean onSlide;
    /** The bars (null without a window). */
    private EnergyBars bars;
    /** The rows the layout's strip was asked for (0: no strip), and for which mode. */
    private int stripRows;
    private boolean stripPresenting;
    /** The strip, text size and rows the bars were last laid out for. */
    private final ScreenRect barsRect = new ScreenRect();
    private float barsTextSize = Float.NaN;
    private int barsRows = -1;
    /** The bars' scale (J per half-bar; 0: choose afresh), kept until it is exceeded. */
    private double barsScale;
    private final StringBuilder barsTitle = new StringBuilder(48);
    /** What the bars ask of the strip (pixels at HUD scale 1; 0: nothing). */
    private float barsWidth;
    private float barsHeight;
    /** What a view below the bars asks of the strip (the lens's graph; 0: nothing). */
    private float belowWidth;
    private float belowHeight;
    /** Scratch: the bars' part of the strip (pixels). */
    private final ScreenRect barsSlot = new ScreenRect();

    @Override
    public void attach(DemoState newDemo) {
        demo = newDemo;
    }

    @Override
    public void declareParameters(DemoParameters parameters) {
        parameters.add(DemoParameter.choice(PARAMETER, "energy ledger",
                new String[] {"off", "on"}, 0, DemoParameter.Applies.LIVE,
                value -> shown = Math.round(value) == 1));
    }

    @Override
    public void buildViews(Application app) {
        bars = new EnergyBars(app.getAssetManager(), HudFont.load(app.getAssetManager()), ROWS);
    }

    /**
     * Keep the demo's own ledger instead of its world's: for particles that are no bodies
     * of the world (the fountain's packed pool). It is kept only while the ledger is wanted
     * (switched on, or on the slide), since it costs O(particles) a step; the demo calls
     * {@link #ownStepped()} after each step of its own simulation. Call in the demo's
     * constructor.
     *
     * @param newOwn the ledger (not null)
     */
    public void useOwnLedger(OwnLedger newOwn) {
        if (newOwn == null) {
            throw new IllegalArgumentException("own ledger must be a ledger, but was null");
        }
        own = newOwn;
    }

    /**
     * After a step of the demo's own simulation, which keeps its own ledger
     * ({@link #useOwnLedger}): the ledger's row for the export, at the world's time.
     */
    public void ownStepped() {
        if (own != null && own.getLedger() != null && table != null) {
            putRow(demo.getWorld().getTimeSeconds());
        }
    }

    @Override
    public void beforeStep(float stepSeconds) {
        if (own != null) {
            // before the demo's own simulation steps: start (from the state now) or stop
            boolean wanted = isDrawn();
            if (wanted != (own.getLedger() != null)) {
                own.keep(wanted);
                if (wanted) {
                    startTable(false);
                }
            }
            if (wanted && table.size() == 0) {
                putRow(demo.getWorld().getTimeSeconds());
            }
            return;
        }
        World world = demo.getWorld();
        if (energy == null) {
            energy = new WorldEnergy(world, false);
            startTable(true);
        }
        energy.beforeStep(world, stepSeconds);
    }

    @Override
    public void afterStep(float stepSeconds) {
        if (own != null || energy == null) {
            return;
        }
        World world = demo.getWorld();
        energy.afterStep(world, stepSeconds);
        putRow(world.getTimeSeconds());
    }

    @Override
    public void onRestart() {
        if (own != null && own.getLedger() != null) {
            // the demo's own reset restarts its ledger, before or after this: the start's
            // row waits for the first step
            own.keep(true);
            startTable(false);
        } else if (energy != null) {
            energy.restart();
            startTable(true);
        }
        barsScale = 0.0;
    }

    /**
     * Once a frame, in a window: ask the layout for the ledger's strip or give it back, and
     * draw the bars in it. Allocates nothing but when the strip comes or goes.
     */
    @Override
    public void afterFrame() {
        if (bars == null || demo.getWindow().getHud() == null) {
            return;
        }
        if (bars.getNode().getParent() == null) {
            // The HUD's node comes and goes with the demo: the bars with it.
            demo.getWindow().getHud().getNode().attachChild(bars.getNode());
        }
        HudLayout layout = demo.getWindow().getHud().getLayout();
        boolean wanted = isDrawn() && hasLedger();
        int rows = wanted ? writeBars() : 0;
        boolean presenting = demo.getDemoHud().isPresenting();
        if (rows != stripRows || rows > 0 && presenting != stripPresenting) {
            // The strip comes, goes, or fits another number of rows (a reset's new columns)
            // or another mode's text.
            stripRows = rows;
            stripPresenting = presenting;
            float size = presenting ? PRESENT_TEXT_FRACTION * HudLayout.PRESENT_SIZE
                    : HudLayout.SCENE_LABEL_SIZE;
            barsWidth = wanted ? bars.widthFor(WIDEST_NAME, size) : 0f;
            barsHeight = wanted ? bars.heightFor(rows, size) : 0f;
            askStrip();
        }
        boolean visible = wanted && !demo.getWindow().getHud().isHelpVisible();
        bars.setVisible(visible);
        if (!visible) {
            return;
        }
        ScreenRect slot = splitStrip(layout, true, barsSlot);
        float textSize = layout.isPresenting()
                ? PRESENT_TEXT_FRACTION * layout.getBodySize() : layout.getSceneLabelSize();
        if (rows != barsRows || !sameRect(slot, barsRect) || textSize != barsTextSize) {
            barsRows = rows;
            barsRect.set(slot);
            barsTextSize = textSize;
            bars.layOut(slot, barsTextSize, WIDEST_NAME);
        }
        bars.refresh();
    }

    @Override
    public void writeHudLines(StringBuilder text) {
        if (!shown) {
            return;
        }
        if (own == null ? energy == null : own.getLedger() == null) {
            text.append("energy ledger: from the first step\n");
            return;
        }
        if (!hasLedger()) {
            text.append("energy ledger: none here: the demo's world has no bodies\n");
            return;
        }
        EnergyLedger ledger = ledger();
        // One short line (a line that wraps as its numbers grow lays the HUD out again): the
        // bars beside the scene hold the columns.
        if (own != null) {
            text.append("energy (J, particles in flight): K+U = start + emitted - removed"
                    + " - losses + numerical;  start ");
        } else {
            text.append("energy (J, all bodies, U = 0 at y = 0): K+U+spring = start + work"
                    + " - losses + numerical;  start ");
        }
        TextFormat.appendFixed(text, ledger.getStartJoules(), 2).append(", numerical ");
        TextFormat.appendFixed(text, ledger.getNumericalJoules(), 4).append('\n');
    }

    /**
     * Ask for room in the strip down the scene's right edge below the bars (or the whole
     * strip while the bars are not drawn): the derivative lens's graph. The strip is as wide
     * as the wider of the two and as high as both with a margin between, at most what the
     * layout allows; each then gets its share of the height. Lays the HUD out again when the
     * request changes. Allocates nothing otherwise.
     *
     * @param widthAtScaleOne the view's width at HUD scale 1 (in pixels, &ge;0; 0: none)
     * @param heightAtScaleOne its height at HUD scale 1 (in pixels, &ge;0; 0: none)
     */
    void askBelowBars(float widthAtScaleOne, float heightAtScaleOne) {
        if (widthAtScaleOne == belowWidth && heightAtScaleOne == belowHeight) {
            return;
        }
        belowWidth = widthAtScaleOne;
        belowHeight = heightAtScaleOne;
        askStrip();
    }

    /**
     * Copy the part of the strip below the bars, as last laid out.
     *
     * @param storeResult storage for the rectangle (in pixels, not null, modified; empty
     *     when nothing was asked for or no window)
     * @return storeResult
     */
    ScreenRect copyBelowBars(ScreenRect storeResult) {
        if (demo.getWindow().getHud() == null) {
            return storeResult.set(0f, 0f, 0f, 0f);
        }
        return splitStrip(demo.getWindow().getHud().getLayout(), false, storeResult);
    }

    /**
     * Show the bars on the slide in presentation mode, switched on or not: for a demo whose
     * slide is about energy. Call in the demo's constructor.
     */
    public void showOnSlide() {
        onSlide = true;
    }

    /**
     * Tell whether the bars are drawn: switched on, or presenting a demo whose slide is
     * about energy ({@link #showOnSlide}).
     *
     * @return true if wanted on screen (in a window, with a ledger)
     */
    public boolean isDrawn() {
        return shown || onSlide && demo.getDemoHud().isPresenting();
    }

    /**
     * Access the bars, for tests.
     *
     * @return the bars, or null without a window
     */
    EnergyBars getBars() {
        return bars;
    }

    /**
     * Access the ledger.
     *
     * @return the live ledger, or null before the demo's first step
     */
    public WorldEnergy getEnergy() {
        return energy;
    }

    /**
     * Access the export's table: {@code t} and the ledger's columns per step since the last
     * reset (those the demo lacks left out).
     *
     * @return the live table, or null before the demo's first step
     */
    public StepTable getTable() {
        return table;
    }

    /**
     * Tell whether there is a ledger to show and export: the world's, once stepped, if it
     * has bodies, or the demo's own while kept.
     *
     * @return true if so
     */
    public boolean hasLedger() {
        if (own != null) {
            return own.getLedger() != null && table != null;
        }
        return energy != null && demo.getWorld().countBodies() > 0;
    }

    /** @return true if the ledger is on the HUD */
    public boolean isShown() {
        return shown;
    }

    /**
     * A table for the ledger's columns now, with the start's row if asked: a new one only if
     * the columns changed, so a reset (a demo's refire) allocates nothing.
     */
    private void startTable(boolean withRow) {
        int columns = columns();
        if (table == null || columns != tableColumns) {
            table = new StepTable(TABLE_NAME, EnergyLedger.csvHeader(columns, "t"),
                    StepTable.DEFAULT_CAPACITY);
            tableColumns = columns;
        } else {
            table.clear();
        }
        if (withRow) {
            putRow(demo.getWorld().getTimeSeconds());
        }
    }

    /** The ledger shown: the demo's own or its world's. */
    private EnergyLedger ledger() {
        return own != null ? own.getLedger() : energy.getLedger();
    }

    /** Its columns. */
    private int columns() {
        return own != null ? own.getColumns() : energy.getColumns();
    }

    /**
     * Set the bars' rows from the ledger now: the demo's columns and the numerical one,
     * losses drawn left of zero; grow the scale if a bar went past it. Allocates nothing but
     * the title's text when the scale changes.
     *
     * @return how many rows are set
     */
    private int writeBars() {
        EnergyLedger ledger = ledger();
        int columns = columns();
        double largest = Math.abs(ledger.getStartJoules());
        bars.setRowCount(1);
        bars.setRow(0, START_NAME, ledger.getStartJoules(), START_COLOR);
        int rows = 1;
        for (int i = 0; i <= EnergyLedger.NUMERICAL_COLUMN; ++i) {
            if (i < EnergyLedger.NUMERICAL_COLUMN && (columns & (1 << i)) == 0) {
                continue;
            }
            double value = ledger.getColumn(i);
            largest = Math.max(largest, Math.abs(value));
            // the losses are taken from the energy: drawn left of zero
            int bit = 1 << i;
            boolean loss = bit == EnergyLedger.DRAG || bit == EnergyLedger.IMPACT
                    || bit == EnergyLedger.REMOVED;
            bars.setRowCount(rows + 1);
            bars.setRow(rows, BAR_NAMES[i], loss ? -value : value, BAR_COLORS[i]);
            ++rows;
        }
        if (largest > barsScale) {
            barsScale = EnergyBars.roundUp(largest);
            bars.setFullScale(barsScale);
            barsTitle.setLength(0);
            barsTitle.append("energy (J), ends at \u00b1");
            TextFormat.appendFixed(barsTitle, barsScale, barsScale < 1.0 ? 3 : 0);
            bars.setTitle(barsTitle);
        }
        return rows;
    }

    /** Ask the layout for a strip that holds the bars and the view below them, if any. */
    private void askStrip() {
        if (demo.getWindow().getHud() == null) {
            return;
        }
        boolean both = barsHeight > 0f && belowHeight > 0f;
        float width = Math.max(barsHeight > 0f ? barsWidth : 0f,
                belowHeight > 0f ? belowWidth : 0f);
        float height = barsHeight + belowHeight + (both ? HudLayout.MARGIN : 0f);
        demo.getWindow().getHud().getLayout().setLedgerSize(width, width > 0f ? height : 0f);
        demo.getWindow().relayOutPanel();
    }

    /**
     * The bars' part of the strip (its top) or the part below them (its bottom): the bars
     * get the height they asked for, as far as the strip holds it, and the view below the
     * rest after a margin (it gives the room up from its plot). Allocates nothing.
     */
    private ScreenRect splitStrip(HudLayout layout, boolean barsPart, ScreenRect storeResult) {
        ScreenRect strip = layout.getLedger();
        float share = barsPart ? barsHeight : belowHeight;
        if (strip.isEmpty() || !(share > 0f)) {
            return storeResult.set(0f, 0f, 0f, 0f);
        }
        if (!(barsHeight > 0f && belowHeight > 0f)) {
            return storeResult.set(strip);
        }
        float barsPixels = Math.min(strip.getHeight(), barsHeight * layout.getScale());
        if (barsPart) {
            return storeResult.set(strip.getX(), strip.getTop() - barsPixels,
                    strip.getWidth(), barsPixels);
        }
        float below = Math.max(0f, strip.getHeight() - barsPixels
                - HudLayout.MARGIN * layout.getScale());
        return storeResult.set(strip.getX(), strip.getY(), strip.getWidth(), below);
    }

    private static boolean sameRect(ScreenRect a, ScreenRect b) {
        return a.getX() == b.getX() && a.getY() == b.getY() && a.getWidth() == b.getWidth()
                && a.getHeight() == b.getHeight();
    }

    private void putRow(double timeSeconds) {
        EnergyLedger ledger = ledger();
        int columns = columns();
        table.startRow().put(timeSeconds);
        for (int i = 0; i < EnergyLedger.NUMERICAL_COLUMN; ++i) {
            if ((columns & (1 << i)) != 0) {
                table.put(ledger.getColumn(i));
            }
        }
        table.put(ledger.getNumericalJoules());
    }

    /**
     * A ledger a demo keeps itself ({@link #useOwnLedger}), switched on and off by this part.
     */
    public interface OwnLedger {

        /**
         * Keep the ledger, starting again from the state now, or stop keeping it.
         *
         * @param keeping true to keep it
         */
        void keep(boolean keeping);

        /**
         * Access the ledger.
         *
         * @return the live ledger while kept, else null
         */
        EnergyLedger getLedger();

        /**
         * Tell which columns it has.
         *
         * @return the columns, OR-ed ({@link EnergyLedger#KINETIC} ...)
         */
        int getColumns();
    }
}
