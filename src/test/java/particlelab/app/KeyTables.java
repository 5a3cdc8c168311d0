package particlelab.app;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;
import particlelab.demo.Draggable;
import particlelab.demo.KeyBinding;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.HelpText;

/**
 * Writes the pages' key tables from the bindings themselves, the way the help overlay is
 * written: a demo's own keys ({@link particlelab.demo.DemoKeys#getBindings()} after the shared
 * ones), the keys every demo shares, the application's (choosing a demo, the window,
 * export: read from the {@link DemoSwitcher} of a {@link ParticleLabApp} built as the window
 * builds it), jME's, and the mouse's gestures (each demo's declared drags).
 * No jME application is started: a demo declares its keys without one.
 *
 * <p>A table is Markdown: one row per binding, its keys in code spans, its description as the
 * help overlay prints it. {@code KeyTablesTest} compares each page's marked block with these
 * and rewrites the blocks when asked.
 */
final class KeyTables {

    /** The block name of the keys every demo shares. */
    static final String SHARED = "shared";
    /** The block name of the application's keys. */
    static final String APPLICATION = "application";
    /** The block name of jME's own keys. */
    static final String JME = "jme";
    /** The block name of the mouse's gestures: every demo's, then each demo's drags. */
    static final String MOUSE = "mouse";
    /** What comes before the range in {@link DemoParameter#appendRange}. */
    private static final String RANGE_FROM = " from ";

    /** Not instantiated: static tools only. */
    private KeyTables() {
    }

    /**
     * Write the table of one demo's own keys, or a sentence saying it has none.
     *
     * @param name the demo's catalogue name, as {@code demo --list} prints it (not null)
     * @return the Markdown, ending in a newline (not null)
     */
    static String demoTable(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        List<KeyBinding> all = demo.getKeys().getBindings();
        List<KeyBinding> shared = sharedBindings(hasGhostKeys(all));
        for (int i = 0; i < shared.size(); ++i) {
            if (!all.get(i).getKeyLabel().equals(shared.get(i).getKeyLabel())) {
                throw new IllegalStateException(name + ": binding " + i + " is "
                        + all.get(i).getKeyLabel() + ", the shared keys have "
                        + shared.get(i).getKeyLabel() + " there");
            }
        }
        List<KeyBinding> own = all.subList(shared.size(), all.size());
        if (own.isEmpty()) {
            return "This demo adds no keys of its own; the keys every demo has are listed in"
                    + " [the shared keys](../keys.md).\n";
        }
        return table(own);
    }

    /**
     * Write the table of the keys every demo has, the exact-ghost keys included (they exist
     * only in the demos that show ghosts).
     *
     * @return the Markdown, ending in a newline (not null)
     */
    static String sharedTable() {
        return table(sharedBindings(true));
    }

    /**
     * Write the table of the application's keys: choosing a demo, the window's, export.
     *
     * @return the Markdown, ending in a newline (not null)
     */
    static String applicationTable() {
        ParticleLabApp app = new ParticleLabApp(DemoCatalog.createAll(), 0, 0, null,
                Float.NaN, false);
        return table(app.getSwitcher().getBindings());
    }

    /**
     * Write jME's own keys, as the help overlay lists them, in a fenced block.
     *
     * @return the Markdown, ending in a newline (not null)
     */
    static String jmeKeys() {
        return "```\n" + new HelpText().jmeKeys() + "```\n";
    }

    /**
     * Write the table of the mouse's gestures, as the help's "Mouse" section lists them: those
     * of every demo (the click that inspects, the camera's), then each demo's declared drags
     * ({@link DemoState#declareDraggables}), in catalogue order; a demo that declares none is
     * named in the last row.
     *
     * @return the Markdown, ending in a newline (not null)
     */
    static String mouseTable() {
        StringBuilder text = new StringBuilder("| demo | gesture | what it does |\n"
                + "|---|---|---|\n");
        List<String[]> every = DragControl.helpRows(List.of());
        for (String[] row : every) {
            mouseRow(text, "every demo", row);
        }
        mouseRow(text, "every demo", new String[] {DragControl.CAMERA_GESTURE + " / wheel",
            "turn / zoom the camera"});
        List<String> without = new ArrayList<>();
        for (String name : DemoCatalog.names()) {
            DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
            List<Draggable> declared = demo.getWindow().getDragControl().getDraggables();
            if (declared.isEmpty()) {
                without.add(name);
            }
            for (Draggable draggable : declared) {
                mouseRow(text, name, new String[] {draggable.getGestureLabel(),
                    draggable.getDescription()});
            }
        }
        if (!without.isEmpty()) {
            text.append("| ").append(String.join(", ", without))
                    .append(" | | nothing to drag (a click still inspects) |\n");
        }
        return text.toString();
    }

    /**
     * Write the block a page marks with {@code <!-- keys:NAME -->}.
     *
     * @param block a demo's name, {@link #SHARED}, {@link #APPLICATION} or {@link #JME}
     * @return the Markdown, ending in a newline (not null)
     */
    static String block(String block) {
        switch (block) {
            case SHARED:
                return sharedTable();
            case APPLICATION:
                return applicationTable();
            case JME:
                return jmeKeys();
            case MOUSE:
                return mouseTable();
            default:
                return demoTable(block);
        }
    }

    /**
     * Write the table of a demo's parameters, the shared step h first, as {@code --set} and
     * the panel take them: name, label, range, default and when a change applies.
     *
     * @param name the demo's catalogue name (not null)
     * @return the Markdown, ending in a newline (not null)
     */
    static String parameterTable(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        DemoParameters parameters = demo.getParameters();
        StringBuilder text = new StringBuilder(
                "| `--set` name | what | range | default | applies |\n|---|---|---|---|---|\n");
        for (int i = 0; i < parameters.size(); ++i) {
            DemoParameter parameter = parameters.get(i);
            text.append("| `").append(parameter.getName()).append("` | ")
                    .append(escape(parameter.getLabel())).append(" | ");
            StringBuilder cell = new StringBuilder();
            if (parameter.isChoice()) {
                // A named state: its names, as --set takes them.
                cell.append("one of ");
                for (int k = 0; k < parameter.countChoices(); ++k) {
                    cell.append(k == 0 ? "" : ", ").append('`').append(parameter.getChoice(k))
                            .append('`');
                }
                text.append(escape(cell.toString())).append(" | ");
            } else {
                parameter.appendRange(cell);
                // appendRange writes "name (label) from A to B": the row has name and label.
                text.append(escape(cell.substring(cell.lastIndexOf(RANGE_FROM)
                        + RANGE_FROM.length()))).append(" | ");
            }
            cell.setLength(0);
            parameter.appendValue(cell, parameter.getDefault());
            text.append(escape(cell.toString())).append(" | ")
                    .append(parameter.getApplies() == DemoParameter.Applies.LIVE
                            ? "live" : "next launch").append(" |\n");
        }
        return text.toString();
    }

    /**
     * Print every block, for a reader who wants to see them: {@code name} then its Markdown.
     *
     * @param args ignored
     */
    public static void main(String[] args) {
        List<String> names = new ArrayList<>(DemoCatalog.names());
        names.add(SHARED);
        names.add(APPLICATION);
        names.add(JME);
        names.add(MOUSE);
        for (String name : names) {
            System.out.println("<!-- keys:" + name + " -->");
            System.out.print(block(name));
            System.out.println("<!-- /keys -->");
        }
        for (String name : DemoCatalog.names()) {
            System.out.println("<!-- params:" + name + " -->");
            System.out.print(parameterTable(name));
            System.out.println("<!-- /params -->");
        }
    }

    /**
     * Test whether a demo's bindings begin with the shared keys of a demo with exact ghosts.
     *
     * @param bindings a demo's bindings, shared first (not null)
     * @return true if its shared keys include the ghost keys
     */
    private static boolean hasGhostKeys(List<KeyBinding> bindings) {
        List<KeyBinding> withGhosts = sharedBindings(true);
        if (bindings.size() < withGhosts.size()) {
            return false;
        }
        for (int i = 0; i < withGhosts.size(); ++i) {
            KeyBinding have = bindings.get(i);
            KeyBinding want = withGhosts.get(i);
            if (!have.getKeyLabel().equals(want.getKeyLabel())
                    || !have.getDescription().equals(want.getDescription())) {
                return false;
            }
        }
        return true;
    }

    /**
     * The shared keys of a demo with no keys of its own, with or without exact ghosts.
     *
     * @param ghosts whether the demo shows exact ghosts (and so has their keys)
     * @return the bindings, in the order a demo lists them
     */
    private static List<KeyBinding> sharedBindings(boolean ghosts) {
        return new BareDemo(ghosts).getKeys().getBindings();
    }

    /**
     * Write bindings as a Markdown table: each binding's keys in code spans, its description.
     *
     * @param bindings the bindings, in the order to list them (not null)
     * @return the table, ending in a newline (not null)
     */
    private static String table(List<KeyBinding> bindings) {
        StringBuilder text = new StringBuilder("| key | what it does |\n|---|---|\n");
        for (KeyBinding binding : bindings) {
            text.append("| ");
            for (int key = 0; key < binding.countKeys(); ++key) {
                text.append(key == 0 ? "" : " / ").append('`')
                        .append(binding.getKeyLabel(key)).append('`');
            }
            text.append(" | ").append(escape(binding.getDescription()))
                    .append(" |\n");
        }
        return text.toString();
    }

    /** Append one row of the mouse table: the demo, the gesture in a code span, what. */
    private static void mouseRow(StringBuilder text, String demo, String[] row) {
        text.append("| ").append(demo).append(" | `").append(row[0]).append("` | ")
                .append(escape(row[1])).append(" |\n");
    }

    /**
     * Escape a description for a table cell: a {@code |} would end the cell and a {@code <}
     * before a letter would start an HTML tag ({@code <demo>}); {@code <->} stays as it is.
     *
     * @param description the text (not null)
     * @return the escaped text (not null)
     */
    private static String escape(String description) {
        return description.replace("|", "\\|").replaceAll("<(?=[A-Za-z/!?])", "\\\\<");
    }

    /** A demo that declares one particle and nothing else: its keys are the shared ones. */
    private static final class BareDemo extends DemoState {

        /** Whether the demo shows exact ghosts (and so has their keys). */
        private final boolean ghosts;

        /**
         * Create the demo.
         *
         * @param ghosts whether it shows exact ghosts
         */
        BareDemo(boolean ghosts) {
            super("bare");
            this.ghosts = ghosts;
        }

        @Override
        protected void createScene() {
            addParticle("ball", ColorRGBA.White, new Vector3f(), new Vector3f(1f, 1f, 0f), 1f,
                    new ParticleIntegrator(new Gravity()));
            if (ghosts) {
                showExactGhosts();
            }
        }
    }
}
