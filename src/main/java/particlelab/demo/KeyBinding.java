package particlelab.demo;

/**
 * One action and the keys that run it: the keys, how each is printed, what the action does
 * (for the help overlay), optionally a short name for the footer, and the action itself, run
 * on the jME thread when one of the keys is pressed. One action may have several keys ("+" and
 * the keypad's "+"); the help shows them on one line. Immutable.
 */
public final class KeyBinding {

    /** What a binding runs when one of its keys is pressed. */
    @FunctionalInterface
    public interface Action {
        /**
         * React to a press.
         *
         * @param keyIndex which of the binding's keys was pressed (&ge;0, in the order given)
         */
        void pressed(int keyIndex);
    }

    /** Between the labels of one binding's keys, as printed. */
    public static final String LABEL_SEPARATOR = " / ";

    private final int[] keyCodes;
    private final String[] keyLabels;
    private final String keyLabel;
    private final String description;
    private final String summary;
    private final Action action;

    /**
     * Create a binding with one key and no footer entry.
     *
     * @param keyCode the key, a {@code com.jme3.input.KeyInput.KEY_*} code (&gt;0)
     * @param keyLabel the key as printed for the help overlay, e.g. "Space" (not null, not
     *     empty)
     * @param description what the key does, e.g. "pause / resume" (not null, not empty)
     * @param action run once per press (not null)
     */
    public KeyBinding(int keyCode, String keyLabel, String description, Runnable action) {
        this(new int[] {keyCode}, new String[] {keyLabel}, description, null,
                runnable(keyLabel, action));
    }

    /**
     * Create a binding with any number of keys.
     *
     * @param keyCodes the keys, {@code com.jme3.input.KeyInput.KEY_*} codes (not null, not
     *     empty, each &gt;0, no repeats; copied)
     * @param keyLabels each key as printed, in the same order (not null, same length, none
     *     null or empty; copied)
     * @param description what the action does, for the help overlay (not null, not empty)
     * @param summary the action in a word or two, for the footer, or null to leave it out
     * @param action run once per press of any of the keys (not null)
     */
    public KeyBinding(int[] keyCodes, String[] keyLabels, String description, String summary,
            Action action) {
        this(keyCodes, keyLabels, null, description, summary, action);
    }

    /**
     * Create a binding, printed with the joined key labels or a label of its own.
     *
     * @param keyCodes the keys (as for the public constructor)
     * @param keyLabels each key as printed (as for the public constructor)
     * @param printedLabel how the help and footer print the keys, e.g. "0-9", or null to join
     *     the key labels
     * @param description what the action does (not null, not empty)
     * @param summary the action in a word or two for the footer, or null
     * @param action run once per press of any of the keys (not null)
     */
    private KeyBinding(int[] keyCodes, String[] keyLabels, String printedLabel,
            String description, String summary, Action action) {
        if (keyCodes == null || keyLabels == null || keyCodes.length == 0
                || keyCodes.length != keyLabels.length) {
            throw new IllegalArgumentException("a binding needs one label per key code and at"
                    + " least one key, but had " + (keyCodes == null ? "no" : keyCodes.length)
                    + " codes and " + (keyLabels == null ? "no" : keyLabels.length) + " labels");
        }
        StringBuilder joined = new StringBuilder();
        for (int i = 0; i < keyCodes.length; ++i) {
            String label = keyLabels[i];
            if (label == null || label.isEmpty()) {
                throw new IllegalArgumentException("key label must be a non-empty text, but was "
                        + (label == null ? "null" : "empty"));
            }
            if (keyCodes[i] <= 0) {
                throw new IllegalArgumentException("key code of " + label + " must be > 0, but"
                        + " was " + keyCodes[i]);
            }
            for (int j = 0; j < i; ++j) {
                if (keyCodes[j] == keyCodes[i]) {
                    throw new IllegalArgumentException("keys " + keyLabels[j] + " and " + label
                            + " have the same key code " + keyCodes[i]);
                }
            }
            joined.append(i == 0 ? "" : LABEL_SEPARATOR).append(label);
        }
        if (description == null || description.isEmpty()) {
            throw new IllegalArgumentException("description of key " + joined
                    + " must be a non-empty text");
        }
        if (summary != null && summary.isEmpty()) {
            throw new IllegalArgumentException("footer summary of key " + joined
                    + " must be null or a non-empty text");
        }
        if (action == null) {
            throw new IllegalArgumentException("action of key " + joined + " must not be null");
        }
        if (printedLabel != null && printedLabel.isEmpty()) {
            throw new IllegalArgumentException("printed label of key " + joined
                    + " must be null or a non-empty text");
        }
        this.keyCodes = keyCodes.clone();
        this.keyLabels = keyLabels.clone();
        this.keyLabel = printedLabel != null ? printedLabel : joined.toString();
        this.description = description;
        this.summary = summary;
        this.action = action;
    }

    /**
     * Copy this binding with a footer entry.
     *
     * @param newSummary the action in a word or two, for the footer (not null, not empty)
     * @return a new binding (not null)
     */
    public KeyBinding withSummary(String newSummary) {
        if (newSummary == null) {
            throw new IllegalArgumentException("footer summary of key " + keyLabel
                    + " must be a non-empty text, but was null");
        }
        return new KeyBinding(keyCodes, keyLabels, keyLabel, description, newSummary, action);
    }

    /**
     * Copy this binding, printed in the help and the footer with a label of its own instead
     * of its keys' labels joined: "0-9" for the ten digits, "Tab / Shift+Tab" for a key whose
     * action reads the Shift key. Each key keeps its own label ({@link #getKeyLabel(int)}).
     *
     * @param printedLabel the label (not null, not empty)
     * @return a new binding (not null)
     */
    public KeyBinding withKeyLabel(String printedLabel) {
        if (printedLabel == null) {
            throw new IllegalArgumentException("printed label of key " + keyLabel
                    + " must be a non-empty text, but was null");
        }
        return new KeyBinding(keyCodes, keyLabels, printedLabel, description, summary, action);
    }

    /** @return how many keys run the action (&ge;1) */
    public int countKeys() {
        return keyCodes.length;
    }

    /**
     * Return one of the keys.
     *
     * @param keyIndex which (&ge;0, &lt;{@link #countKeys()})
     * @return its jME key code
     */
    public int getKeyCode(int keyIndex) {
        return keyCodes[keyIndex];
    }

    /**
     * Return how one of the keys is printed.
     *
     * @param keyIndex which (&ge;0, &lt;{@link #countKeys()})
     * @return its label (not null)
     */
    public String getKeyLabel(int keyIndex) {
        return keyLabels[keyIndex];
    }

    /**
     * @return every key as printed, joined by {@link #LABEL_SEPARATOR}, e.g. "+ / keypad +",
     *     or the label given to {@link #withKeyLabel}
     */
    public String getKeyLabel() {
        return keyLabel;
    }

    /** @return what the action does (not null) */
    public String getDescription() {
        return description;
    }

    /** @return the action in a word or two for the footer, or null if not in the footer */
    public String getSummary() {
        return summary;
    }

    /**
     * Run the action, as a press of one of the keys does.
     *
     * @param keyIndex which key was pressed (&ge;0, &lt;{@link #countKeys()})
     */
    public void press(int keyIndex) {
        if (keyIndex < 0 || keyIndex >= keyCodes.length) {
            throw new IllegalArgumentException("key index must be from 0 to "
                    + (keyCodes.length - 1) + ", but was " + keyIndex);
        }
        action.pressed(keyIndex);
    }

    @Override
    public String toString() {
        return keyLabel + ": " + description;
    }

    private static Action runnable(String keyLabel, Runnable action) {
        if (action == null) {
            throw new IllegalArgumentException("action of key " + keyLabel + " must not be null");
        }
        return keyIndex -> action.run();
    }
}
