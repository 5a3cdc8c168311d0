package particlelab.demo;

import com.jme3.app.Application;
import particlelab.view.HudLayout;
import particlelab.world.StateRecord;

/**
 * A piece of a demo with hooks of its own, such as the free-flight demos'
 * {@link ComparisonLane}: added once with {@link DemoState#addPart}, it is then called by the
 * demo at the same moments as the demo's own hooks of the same names, so the demo does not
 * forward them by hand. {@link DemoState} calls each hook right after the demo's own hook,
 * the parts in the order they were added: a part's parameters come after the demo's in the
 * panel and {@code --set}, its keys after the demo's keys, its HUD lines after the demo's
 * lines, its slide after the demo's slide. Every hook does nothing by default; a part
 * overrides those it needs.
 *
 * <p>The hooks in their lifecycle order: {@link #attach} (the demo's constructor), then
 * {@link #declareParameters}; when the scene is declared, {@link #stateRecord},
 * {@link #declareKeys} and {@link #declareDraggables}; in a window {@link #buildViews} and
 * {@link #layOut} (again at every new layout); then every step {@link #beforeStep} and
 * {@link #afterStep}, every frame {@link #afterFrame}, {@link #writeHudLines} and while
 * presenting {@link #writePresentation}; at a reset {@link #onRestart}.
 *
 * <p>The step hooks, {@link #afterFrame()}, {@link #writeHudLines} and
 * {@link #writePresentation} run every step or frame: like the demo's, they must allocate
 * nothing.
 */
public interface DemoPart {

    /**
     * Meet the demo the part was added to. Called once, by {@link DemoState#addPart}, before
     * any other hook. The default does nothing.
     *
     * @param demo the demo (not null; still being constructed: keep it, call nothing on it)
     */
    default void attach(DemoState demo) {
    }

    /**
     * Declare the part's parameters, after the demo's own
     * ({@link DemoState#declareParameters()}). The default declares none.
     *
     * @param parameters where to declare them (not null, modified)
     */
    default void declareParameters(DemoParameters parameters) {
    }

    /**
     * Declare the part's keys, after the demo's own ({@link DemoState#declareKeys()}), with
     * the demo's {@code bindKey}. The default declares none.
     */
    default void declareKeys() {
    }

    /**
     * Build the part's own views and attach them to the demo's scene node, after the demo's
     * own ({@link DemoState#buildViews}). Called once, only in a window. The default builds
     * none.
     *
     * @param app the application whose assets the views use (not null)
     */
    default void buildViews(Application app) {
    }

    /**
     * Act at the start of a step, after the demo's {@link DemoState#beforeStep}, before
     * anything moves. The default does nothing.
     *
     * @param stepSeconds h of the step about to be taken (in seconds, &gt;0)
     */
    default void beforeStep(float stepSeconds) {
    }

    /**
     * Observe a step once every particle moved, after the demo's
     * {@link DemoState#afterStep}; move nothing. The default does nothing.
     *
     * @param stepSeconds h of the step just taken (in seconds, &gt;0)
     */
    default void afterStep(float stepSeconds) {
    }

    /**
     * React to a reset, after the demo's {@link DemoState#onRestart()}. The default does
     * nothing.
     */
    default void onRestart() {
    }

    /**
     * React to one frame once the clock's steps are over, after the demo's
     * {@link DemoState#afterFrame()} and before the views move. The default does nothing.
     */
    default void afterFrame() {
    }

    /**
     * Append the part's HUD lines, each ending in a newline, after the demo's own
     * ({@link DemoState#writeHudLines}). The default appends none.
     *
     * @param text where to append (not null, modified)
     */
    default void writeHudLines(StringBuilder text) {
    }

    /**
     * Return the state of the part's own that its steps change and its next step reads, so a
     * step back and a replay give the same bits (as {@link DemoState#addStateRecord}). Asked
     * once, right after the demo's {@link DemoState#createScene()}. The default has none.
     *
     * @return the record, or null for none
     */
    default StateRecord stateRecord() {
        return null;
    }

    /**
     * Declare what the mouse may drag, after the demo's own
     * ({@link DemoState#declareDraggables()}), with the demo's {@code declareDraggable}.
     * The default declares none.
     */
    default void declareDraggables() {
    }

    /**
     * Lay the part's own views out for the HUD's layout, right after the scene's area
     * followed it: at the first layout, a new window size or HUD factor, a slot that came or
     * went, presentation mode. Only in a window. The default does nothing.
     *
     * @param layout the HUD's layout (not null, do not modify)
     */
    default void layOut(HudLayout layout) {
    }

    /**
     * Add to the slide presentation mode shows, after the demo's own
     * ({@link DemoState#writePresentation}): only what the demo left free (a slide holds
     * one readout and at most two formula lines, {@link Presentation}). Called every frame
     * while presenting. The default adds nothing.
     *
     * @param slide where to write (not null, modified)
     */
    default void writePresentation(Presentation slide) {
    }
}
