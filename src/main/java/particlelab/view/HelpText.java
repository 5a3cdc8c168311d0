package particlelab.view;

/**
 * Builds the help overlay's text from key bindings, so the help can never drift from the keys
 * actually bound: headings, then one line per key.
 */
public final class HelpText {

    private final StringBuilder text = new StringBuilder();

    /**
     * Start a section.
     *
     * @param heading the section's heading (not null)
     * @return this
     */
    public HelpText section(String heading) {
        if (text.length() > 0) {
            text.append('\n');
        }
        text.append(heading).append('\n');
        return this;
    }

    /**
     * Add one key's line.
     *
     * @param keyLabel the key as printed on the keyboard, e.g. "Space" (not null)
     * @param description what it does (not null)
     * @return this
     */
    public HelpText key(String keyLabel, String description) {
        text.append("   ").append(keyLabel).append("  -  ").append(description).append('\n');
        return this;
    }

    /**
     * Add one line holding two keys' entries, for a list too long to give a line each (the
     * demos by number): "key  -  description;   key  -  description".
     *
     * @param keyLabel the first key (not null)
     * @param description what it does (not null)
     * @param secondKeyLabel the second key (not null)
     * @param secondDescription what that one does (not null)
     * @return this
     */
    public HelpText keys(String keyLabel, String description, String secondKeyLabel,
            String secondDescription) {
        text.append("   ").append(keyLabel).append("  -  ").append(description).append(";   ")
                .append(secondKeyLabel).append("  -  ").append(secondDescription).append('\n');
        return this;
    }

    /**
     * Add the section of jME's own keys and the camera's, which every window has.
     *
     * @return this
     */
    public HelpText jmeKeys() {
        section("jME's keys and the camera");
        key("Esc", "quit the app");
        key("F5 / M", "jME's frame statistics / memory use (console)");
        key("right drag / wheel", "turn / zoom the camera;  W A S D Q Z  fly;  R  reframes");
        return this;
    }

    @Override
    public String toString() {
        return text.toString();
    }
}
