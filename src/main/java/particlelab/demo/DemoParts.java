package particlelab.demo;

import com.jme3.app.Application;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.HudLayout;
import particlelab.world.StateRecord;

/**
 * A demo's hooks in their fixed order, beside its base class: at each moment the demo's own
 * hook first, then the same hook of every {@link DemoPart} in the order the parts were added
 * (the energy ledger first). The demo calls one method here per moment, so neither it nor a
 * demo forwards a part's hook by hand. The step, frame and HUD methods allocate nothing.
 */
final class DemoParts {

    private final DemoState demo;
    private final List<DemoPart> parts = new ArrayList<>();

    /** @param demo the demo whose own hooks come first (not null; still being constructed) */
    DemoParts(DemoState demo) {
        this.demo = demo;
    }

    /**
     * Add a part, after the demo checked it may, and let it meet the demo.
     *
     * @param part the part (not null, not added yet)
     */
    void add(DemoPart part) {
        if (parts.contains(part)) {
            throw new IllegalArgumentException("demo part " + part + " was added already");
        }
        parts.add(part);
        part.attach(demo);
    }

    /** @param parameters the demo's parameters: the demo's own, then each part's (modified) */
    void declareParameters(DemoParameters parameters) {
        demo.declareParameters();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).declareParameters(parameters);
        }
    }

    /** @param run where each part's state record goes, after the demo's scene (modified) */
    void addStateRecords(DemoRun run) {
        for (int i = 0; i < parts.size(); ++i) {
            StateRecord record = parts.get(i).stateRecord();
            if (record != null) {
                run.addStateRecord(record);
            }
        }
    }

    /** The demo's keys, then each part's; the demo's draggables, then each part's. */
    void declareKeysAndDraggables() {
        demo.declareKeys();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).declareKeys();
        }
        demo.declareDraggables();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).declareDraggables();
        }
    }

    /** @param app the application whose assets the views use: the demo's, then each part's */
    void buildViews(Application app) {
        demo.buildViews(app);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).buildViews(app);
        }
    }

    /** @param layout the HUD's new layout, which the scene's area followed (not modified) */
    void layOut(HudLayout layout) {
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).layOut(layout);
        }
    }

    /** @param stepSeconds h of the step about to be taken (in seconds, &gt;0) */
    void beforeStep(float stepSeconds) {
        demo.beforeStep(stepSeconds);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).beforeStep(stepSeconds);
        }
    }

    /** @param stepSeconds h of the step just taken (in seconds, &gt;0) */
    void afterStep(float stepSeconds) {
        demo.afterStep(stepSeconds);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).afterStep(stepSeconds);
        }
    }

    /** After a reset: the demo's reaction, then each part's. */
    void onRestart() {
        demo.onRestart();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).onRestart();
        }
    }

    /** Once a frame, after the clock's steps: the demo's reaction, then each part's. */
    void afterFrame() {
        demo.afterFrame();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).afterFrame();
        }
    }

    /** @param text where the demo's own HUD lines go, then each part's (modified) */
    void writeHudLines(StringBuilder text) {
        demo.writeHudLines(text);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).writeHudLines(text);
        }
    }

    /** @param slide where the demo's slide goes, then each part's (emptied before, modified) */
    void writePresentation(Presentation slide) {
        demo.writePresentation(slide);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).writePresentation(slide);
        }
    }
}
