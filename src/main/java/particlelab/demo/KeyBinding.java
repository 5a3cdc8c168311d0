package particlelab.demo;

/**
 * One key a demo declares: the key, how it is printed in the help overlay, and the action run
 * on the jME thread when it is pressed. Immutable.
 */
public final class KeyBinding {

    private final int keyCode;
    private final String keyLabel;
    private final String description;
    private final Runnable action;

    /**
     * Create a binding.
     *
     * @param keyCode the key, a {@code com.jme3.input.KeyInput.KEY_*} code (&gt;0)
     * @param keyLabel the key as printed for the help overlay, e.g. "Space" (not null, not
     *     empty)
     * @param description what the key does, e.g. "pause / resume" (not null, not empty)
     * @param action run once per press (not null)
     */
    public KeyBinding(int keyCode, String keyLabel, String description, Runnable action) {
        if (keyCode <= 0) {
            throw new IllegalArgumentException("key code must be > 0, but was " + keyCode);
        }
        if (keyLabel == null || keyLabel.isEmpty()) {
            throw new IllegalArgumentException("key label must be a non-empty text, but was "
                    + (keyLabel == null ? "null" : "empty"));
        }
        if (description == null || description.isEmpty()) {
            throw new IllegalArgumentException("description of key " + keyLabel
                    + " must be a non-empty text");
        }
        if (action == null) {
            throw new IllegalArgumentException("action of key " + keyLabel + " must not be null");
        }
        this.keyCode = keyCode;
        this.keyLabel = keyLabel;
        this.description = description;
        this.action = action;
    }

    /** @return the jME key code */
    public int getKeyCode() {
        return keyCode;
    }

    /** @return the key as printed in the help overlay (not null) */
    public String getKeyLabel() {
        return keyLabel;
    }

    /** @return what the key does (not null) */
    public String getDescription() {
        return description;
    }

    /** @return the action run on each press (not null) */
    public Runnable getAction() {
        return action;
    }

    @Override
    public String toString() {
        return keyLabel + ": " + description;
    }
}
