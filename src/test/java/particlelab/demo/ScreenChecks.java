package particlelab.demo;

import java.util.ArrayList;
import java.util.List;
import particlelab.view.ScreenRect;

/** The window checks the layout tests share. */
final class ScreenChecks {

    private ScreenChecks() {
    }

    /**
     * Check that the non-empty rectangles are inside the window and that no two intersect.
     *
     * @param rects the texts' (and slots') rectangles, in pixels (not null, not modified)
     * @param width the window's width (pixels)
     * @param height the window's height (pixels)
     * @param where what was laid out, for the messages (not null)
     * @return one line per problem (empty if none)
     */
    static List<String> textsApartInside(List<ScreenRect> rects, int width, int height,
            String where) {
        List<String> problems = new ArrayList<>();
        ScreenRect window = new ScreenRect(0f, 0f, width, height);
        for (int i = 0; i < rects.size(); ++i) {
            if (rects.get(i).isEmpty()) {
                continue;
            }
            if (!window.contains(rects.get(i))) {
                problems.add(where + ": text " + i + " " + rects.get(i) + " leaves the window");
            }
            for (int j = 0; j < i; ++j) {
                if (rects.get(i).intersects(rects.get(j))) {
                    problems.add(where + ": text " + i + " " + rects.get(i) + " covers text "
                            + j + " " + rects.get(j));
                }
            }
        }
        return problems;
    }
}
