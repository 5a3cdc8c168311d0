package particlelab.demo;

/**
 * Lines a demo's HUD shows after its own, written from the demo's live numbers at each HUD
 * refresh: the lecture tour's "what to watch for" ({@code particlelab.app.LectureTour}).
 * Writing them allocates nothing.
 */
@FunctionalInterface
public interface HudNote {

    /**
     * Append the lines, each ending with a line feed, allocating nothing.
     *
     * @param demo the demo whose HUD it is (not null; read its numbers, change nothing)
     * @param text where to append (not null, modified)
     */
    void append(DemoState demo, StringBuilder text);
}
