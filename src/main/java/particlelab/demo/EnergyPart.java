package particlelab.demo;

import particlelab.physics.EnergyLedger;
import particlelab.view.TextFormat;
import particlelab.world.World;
import particlelab.world.WorldEnergy;

/**
 * Where the energy goes (issue 32): every demo's part that keeps the {@link WorldEnergy}
 * ledger of its world, records it for the export ({@code energy.csv}, one row per step) and,
 * when shown (the panel's "energy ledger", {@code --set energy=on}), writes it on the HUD as
 * a bar per
 * column: kinetic, potential, spring, thrust work, drag loss, impact loss, script work and
 * the numerical column, the energy the steps themselves created or destroyed.
 *
 * <p>Hidden by default: the ledger takes up to ten HUD lines, which would crowd every demo's
 * own readouts; the lecturer shows it where the slide is about energy. A parameter rather
 * than a key: every letter is taken by some demo, and a part's key would sit among each
 * demo's own keys.
 *
 * <p>The ledger starts at the demo's first step and again at every reset. Its step hooks
 * and HUD lines allocate nothing.
 */
public final class EnergyPart implements DemoPart {

    /** The parameter's name ({@code --set energy=on}). */
    public static final String PARAMETER = "energy";
    /** The export's table name: {@code energy.csv}. */
    public static final String TABLE_NAME = "energy";
    /** The widest bar on the HUD (in characters). */
    private static final int BAR_CHARACTERS = 24;
    /** The HUD's names of the columns, in {@link EnergyLedger#getColumn}'s order. */
    private static final String[] HUD_NAMES = {"kinetic", "potential", "spring",
        "thrust work", "drag loss", "impact loss", "script work", "NUMERICAL"};

    private DemoState demo;
    private WorldEnergy energy;
    private StepTable table;
    /** The columns {@link #table} was made for. */
    private int tableColumns;
    private boolean shown;

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
    public void beforeStep(float stepSeconds) {
        World world = demo.getWorld();
        if (energy == null) {
            energy = new WorldEnergy(world, false);
            startTable();
        }
        energy.beforeStep(world, stepSeconds);
    }

    @Override
    public void afterStep(float stepSeconds) {
        if (energy == null) {
            return;
        }
        World world = demo.getWorld();
        energy.afterStep(world, stepSeconds);
        putRow(world.getTimeSeconds());
    }

    @Override
    public void onRestart() {
        if (energy != null) {
            energy.restart();
            startTable();
        }
    }

    @Override
    public void writeHudLines(StringBuilder text) {
        if (!shown) {
            return;
        }
        if (energy == null) {
            text.append("energy ledger: from the first step\n");
            return;
        }
        if (demo.getWorld().countBodies() == 0) {
            text.append("energy ledger: none here: the demo's world has no bodies\n");
            return;
        }
        EnergyLedger ledger = energy.getLedger();
        int columns = energy.getColumns();
        double largest = Math.abs(ledger.getStartJoules());
        for (int i = 0; i <= EnergyLedger.NUMERICAL_COLUMN; ++i) {
            largest = Math.max(largest, Math.abs(ledger.getColumn(i)));
        }
        text.append("energy (J, all bodies, U = 0 at y = 0): K + U + spring = start ");
        TextFormat.appendFixed(text, ledger.getStartJoules(), 2)
                .append(" + thrust - drag - impacts + script + numerical\n");
        for (int i = 0; i <= EnergyLedger.NUMERICAL_COLUMN; ++i) {
            if (i < EnergyLedger.NUMERICAL_COLUMN && (columns & (1 << i)) == 0) {
                continue;
            }
            double value = ledger.getColumn(i);
            // the name and value first, then the bar: the HUD's font is proportional
            text.append("  ").append(HUD_NAMES[i]).append(' ');
            TextFormat.appendFixed(text, value, 2).append("   ");
            int length = largest > 0.0
                    ? (int) Math.round(BAR_CHARACTERS * Math.abs(value) / largest) : 0;
            if (length == 0 && value != 0.0) {
                length = 1;
            }
            char mark = i == EnergyLedger.NUMERICAL_COLUMN ? '%' : '#';
            for (int k = 0; k < length; ++k) {
                text.append(mark);
            }
            if (i == EnergyLedger.NUMERICAL_COLUMN) {
                text.append("  the step's own");
            }
            text.append('\n');
        }
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

    /** @return true if the ledger is on the HUD */
    public boolean isShown() {
        return shown;
    }

    /**
     * A table for the ledger's columns now, with the start's row: a new one only if the
     * columns changed, so a reset (a demo's refire) allocates nothing.
     */
    private void startTable() {
        int columns = energy.getColumns();
        if (table == null || columns != tableColumns) {
            table = new StepTable(TABLE_NAME, EnergyLedger.csvHeader(columns, "t"),
                    StepTable.DEFAULT_CAPACITY);
            tableColumns = columns;
        } else {
            table.clear();
        }
        putRow(demo.getWorld().getTimeSeconds());
    }

    private void putRow(double timeSeconds) {
        EnergyLedger ledger = energy.getLedger();
        int columns = energy.getColumns();
        table.startRow().put(timeSeconds);
        for (int i = 0; i < EnergyLedger.NUMERICAL_COLUMN; ++i) {
            if ((columns & (1 << i)) != 0) {
                table.put(ledger.getColumn(i));
            }
        }
        table.put(ledger.getNumericalJoules());
    }
}
