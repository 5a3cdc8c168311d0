package particlelab.app;

import com.jme3.input.KeyInput;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.HudNote;
import particlelab.demo.KeyBinding;

/**
 * Walks the {@link LectureTour} in the window: a stop selects its demo, puts every parameter
 * of it back to its default, applies the stop's settings (as {@code --set} does) and shows
 * the stop's heading and "what to watch for" under the demo's HUD, and its number and slide
 * after the demo's title ("1/22 Collision Response", in presentation mode too). PageDown and
 * PageUp go forward and back; F7 starts the tour at its first stop, or leaves it. The keys are
 * the application's, listed in every demo's help.
 */
final class TourGuide {

    /** The stop index while not touring. */
    static final int NOT_TOURING = -1;

    private final DemoSwitcher switcher;
    /** Per stop: its heading, then its watch lines. */
    private final List<HudNote> notes = new ArrayList<>();
    private final List<KeyBinding> bindings = new ArrayList<>();
    private int stop = NOT_TOURING;

    /**
     * Create the guide.
     *
     * @param switcher the window's demos, in {@link DemoCatalog} order (not null)
     */
    TourGuide(DemoSwitcher switcher) {
        this.switcher = switcher;
        List<LectureTour.Stop> stops = LectureTour.stops();
        for (int i = 0; i < stops.size(); ++i) {
            int index = i;
            HudNote watch = stops.get(i).getWatch();
            notes.add((demo, text) -> {
                LectureTour.appendHeading(text, index);
                watch.append(demo, text);
            });
        }
        int count = stops.size();
        bindings.add(new KeyBinding(KeyInput.KEY_PGDN, "PageDown",
                "lecture tour: next stop (slide)",
                () -> go(stop < 0 ? 0 : Math.min(count - 1, stop + 1))));
        bindings.add(new KeyBinding(KeyInput.KEY_PGUP, "PageUp",
                "lecture tour: previous stop", () -> go(stop < 0 ? 0 : Math.max(0, stop - 1))));
        bindings.add(new KeyBinding(KeyInput.KEY_F7, "F7",
                "lecture tour: start at stop 1 (" + count + " stops, lecture 15) / leave it",
                () -> {
                    if (stop < 0) {
                        go(0);
                    } else {
                        leave();
                    }
                }));
    }

    /**
     * Return the guide's keys, for the application's list.
     *
     * @return an unmodifiable list (not null)
     */
    List<KeyBinding> getBindings() {
        return Collections.unmodifiableList(bindings);
    }

    /** @return the stop shown (from 0), or {@link #NOT_TOURING} */
    int getStop() {
        return stop;
    }

    /**
     * Go to a stop: its demo, its state, its lines on the HUD.
     *
     * @param index the stop (from 0, less than the stops' count)
     * @throws UsageException if a stop's setting is refused (a test checks none is)
     */
    void go(int index) {
        List<LectureTour.Stop> stops = LectureTour.stops();
        if (index < 0 || index >= stops.size()) {
            throw new IllegalArgumentException("tour stop index must be from 0 to "
                    + (stops.size() - 1) + ", but was " + index);
        }
        if (switcher.getDemos().size() != DemoCatalog.names().size()) {
            // A window on a few demos (a test's) has not every stop's demo.
            switcher.getSelected().showNotice("the lecture tour needs every demo: run"
                    + " particle-lab tour or particle-lab demo");
            return;
        }
        leave();
        LectureTour.Stop next = stops.get(index);
        int demoIndex = DemoCatalog.indexOf(next.getDemo());
        DemoState demo = switcher.getDemos().get(demoIndex);
        DemoParameters parameters = demo.getParameters();
        for (int i = 0; i < parameters.size(); ++i) {
            parameters.set(i, parameters.get(i).getDefault());
        }
        DemoCommand.applySettings(demo, next.getSettings());
        if (parameters.isStarted()) {
            // A launch value waits for the next launch: the stop starts from the launch.
            demo.restart();
        }
        demo.setNote(notes.get(index));
        // The title names the stop in both modes: presentation mode shows no heading line.
        demo.setTitleNote(LectureTour.titleNote(index));
        switcher.select(demoIndex);
        stop = index;
    }

    /** Leave the tour: the stop's lines go from its demo's HUD; the demo stays as it is. */
    void leave() {
        if (stop >= 0) {
            int demoIndex = DemoCatalog.indexOf(LectureTour.stops().get(stop).getDemo());
            switcher.getDemos().get(demoIndex).setNote(null);
            switcher.getDemos().get(demoIndex).setTitleNote(null);
        }
        stop = NOT_TOURING;
    }
}
