package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The HUD's layout as pure arithmetic, with a monospaced stand-in for the font (every
 * character 0.5 of the size wide, lines 1.2 of the size high): no jME, no rendering.
 */
class HudLayoutTest {

    /** A monospaced measure: width 0.5·size per character, line height 1.2·size. */
    private static final TextMeasure MONO = new TextMeasure() {
        @Override
        public float width(CharSequence text, float size) {
            int widest = 0;
            int line = 0;
            for (int i = 0; i < text.length(); ++i) {
                line = text.charAt(i) == '\n' ? 0 : line + 1;
                widest = Math.max(widest, line);
            }
            return 0.5f * size * widest;
        }

        @Override
        public float lineHeight(float size) {
            return 1.2f * size;
        }
    };

    private static final String BODY = "a = g + F/m,  m = 1 kg,  V0 = (10, 10, 0) m/s;   linear:"
            + " F = -b V, b = 0.9 N s/m;   quadratic: F = -c |V| V, c = 0.064 kg/m\n"
            + "t = 1.62 s\nball:  P = (16.17, 3.23, 0.00) m   V = (10.00, -5.84, 0.00) m/s\n"
            + "Stepping: fixed h = 16.7 ms   time x1.00";

    /** Presentation mode's slide: the drag demo's two formula lines and its readout. */
    private static final String SLIDE = "linear:  a = g - (b/m)V,   b/m = 0.90 /s\n"
            + "quadratic:  a = g - (c/m)|V|V,   c/m = 0.064 /m";
    private static final String READOUT = "|V|:  gravity only 11.84,  linear 8.10,  quadratic"
            + " 9.02 m/s";

    private static final String FOOTER =
            "H  help     Space  pause     N  step     R  reset     Tab / 1-9  next demo";

    @ParameterizedTest
    @CsvSource({"1024, 768", "1280, 720", "1920, 1080", "3840, 2160", "800, 600"})
    void hudBlocksNeverOverlapAndStayInsideTheWindow(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        layout.layOut(width, height, HudLayout.scaleFor(width, height), "3.  Drag", BODY,
                "H  help     Space  pause     N  step     R  reset     Tab / 1-9  next demo",
                help(40));
        List<ScreenRect> blocks = List.of(layout.getTitle(), layout.getBody(),
                layout.getWarning(), layout.getFooter());
        for (int i = 0; i < blocks.size(); ++i) {
            assertTrue(layout.getWindow().contains(blocks.get(i)), blocks.get(i).toString());
            assertFalse(blocks.get(i).isEmpty(), "block " + i);
            for (int j = 0; j < i; ++j) {
                assertFalse(blocks.get(i).intersects(blocks.get(j)), i + " over " + j);
            }
        }
        assertSceneUnderTheTextAndOverTheFooter(layout);
        // The long equation line was wrapped to the window, not clipped.
        assertTrue(layout.getBody().getWidth() <= width - 2f * layout.getMargin());
        assertTrue(MONO.width(layout.wrap(BODY, layout.getBodySize(),
                layout.getBody().getWidth()), layout.getBodySize())
                <= layout.getBody().getWidth());
    }

    @ParameterizedTest
    @CsvSource({"1024, 768", "1280, 720", "1920, 1080", "3840, 2160"})
    void sidePanelAndGraphTakeTheirOwnPlaceAndTheTextWrapsLeftOfThePanel(int width,
            int height) {
        HudLayout layout = new HudLayout(MONO);
        layout.setPanelWidth(320f);
        layout.setGraphSize(360f, 200f);
        layout.layOut(width, height, HudLayout.scaleFor(width, height), "3.  Drag", BODY,
                "H  help     Space  pause     N  step     R  reset     Tab / 1-9  next demo",
                help(40));
        ScreenRect panel = layout.getSidePanel();
        ScreenRect graph = layout.getGraph();
        assertFalse(panel.isEmpty());
        assertFalse(graph.isEmpty());
        assertTrue(layout.getWindow().contains(panel), panel.toString());
        assertTrue(layout.getScene().contains(graph), graph + " in " + layout.getScene());
        for (ScreenRect text : List.of(layout.getTitle(), layout.getBody(),
                layout.getWarning(), layout.getFooter())) {
            assertFalse(text.intersects(panel), text + " over the panel " + panel);
            assertFalse(text.intersects(graph), text + " over the graph " + graph);
        }
        assertFalse(layout.getScene().intersects(panel), "the scene runs under the panel");
        // The body wraps to its own width, left of the panel.
        assertTrue(MONO.width(layout.wrap(BODY, layout.getBodySize(),
                layout.getBody().getWidth()), layout.getBodySize())
                <= layout.getBody().getWidth());

        layout.setPanelWidth(0f);
        layout.setGraphSize(0f, 0f);
        layout.layOut(width, height, HudLayout.scaleFor(width, height), "3.  Drag", BODY,
                "footer", help(40));
        assertTrue(layout.getSidePanel().isEmpty());
        assertTrue(layout.getGraph().isEmpty());
        assertEquals(width, layout.getScene().getWidth(), 0f, "no panel: the scene is as wide"
                + " as the window");
    }

    @ParameterizedTest
    @CsvSource({"1024, 768", "1280, 720", "1920, 1080", "3840, 2160", "640, 360"})
    void helpFitsInColumnsBelowTheTitleWithTheDemosKeysFirst(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        String help = help(45);
        layout.layOut(width, height, HudLayout.scaleFor(width, height), "5.  HelloAiming",
                BODY, "H  help", help);
        List<ScreenRect> columns = layout.getHelpColumns();
        assertTrue(columns.size() >= 1);
        for (int i = 0; i < columns.size(); ++i) {
            ScreenRect column = columns.get(i);
            assertTrue(layout.getHelpPanel().contains(column), column.toString());
            assertFalse(column.intersects(layout.getTitle()), column.toString());
            for (int j = 0; j < i; ++j) {
                assertFalse(column.intersects(columns.get(j)));
            }
        }
        assertTrue(layout.getWindow().contains(layout.getHelpPanel()));
        // Reading order: the first column starts with the demo's own section.
        assertTrue(layout.getHelpColumnTexts().get(0).startsWith("Demo - keys\n   F  -  fire"));
        // Every line of the help is shown, once.
        List<String> shown = new ArrayList<>();
        for (String text : layout.getHelpColumnTexts()) {
            for (String line : text.split("\n")) {
                if (!line.isEmpty()) {
                    shown.add(line);
                }
            }
        }
        List<String> expected = new ArrayList<>();
        for (String line : help.split("\n")) {
            if (!line.isEmpty()) {
                expected.add(line);
            }
        }
        assertEquals(expected, shown);
    }

    @ParameterizedTest
    @CsvSource({"200, 150", "320, 240", "400, 300", "640, 360"})
    void aSmallWindowHidesHudLinesFooterFirstAndKeepsTheSceneItsShare(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        String body = lines(30);
        layout.layOut(width, height, HudScale.MIN_SCALE, "3.  Drag", body, FOOTER, help(40));
        assertTrue(layout.isTooSmall());
        // The text is smaller than the scale that suits the window, at the factor 1 asked.
        assertEquals("text x1.0 reduced to x" + oneDecimal(HudScale.MIN_SCALE
                / HudLayout.scaleFor(width, height)) + ": window too small (" + width + "x"
                + height + "), HUD lines hidden", layout.getFooterText().replace("\n    ", " "));
        assertTrue(layout.getBodyLines() < layout.getBodyLinesNeeded(),
                layout.getBodyLines() + " of " + layout.getBodyLinesNeeded());
        assertTrue(layout.getScene().getHeight() >= HudLayout.MIN_SCENE_SHARE * height,
                layout.getScene().toString());
        List<ScreenRect> blocks = List.of(layout.getTitle(), layout.getBody(),
                layout.getWarning(), layout.getFooter());
        for (int i = 0; i < blocks.size(); ++i) {
            assertTrue(layout.getWindow().contains(blocks.get(i)), i + " " + blocks.get(i));
            for (int j = 0; j < i; ++j) {
                assertFalse(blocks.get(i).intersects(blocks.get(j)), i + " over " + j);
            }
        }
        assertSceneUnderTheTextAndOverTheFooter(layout);
        // The lines shown fill the band: as many as its height holds, the first ones.
        assertEquals(layout.getBodyLines() * MONO.lineHeight(layout.getBodySize()),
                layout.getBody().getHeight(), 1e-3f);
        assertEquals(lines(layout.getBodyLines()).strip(),
                HudLayout.firstLines(body, layout.getBodyLines()).toString().strip());
    }

    @Test
    void theBodysBandStopsGrowingWhereTheScenesShareBegins() {
        // Issue 17: the band kept the most lines the body ever needed, so lines added by keys
        // grew it until the scene had no height left.
        HudLayout layout = new HudLayout(MONO);
        for (int count = 1; count <= 60; ++count) {
            layout.layOut(800, 450, HudScale.MIN_SCALE, "3.  Drag", lines(count), FOOTER,
                    help(40));
            assertTrue(layout.getScene().getHeight() >= HudLayout.MIN_SCENE_SHARE * 450f,
                    count + " lines: " + layout.getScene());
            assertTrue(layout.getWindow().contains(layout.getBody()), count + " lines");
        }
        assertEquals(60, layout.getBodyLinesNeeded());
    }

    /**
     * Issue 29 §3: the hall command's slide (1920x1080, the scale that suits it, 1.5, times
     * 1.25) leaves the scene at least {@link HudLayout#PRESENT_SCENE_SHARE} of the height:
     * the second formula row is hidden and the footer says so; a title wider than the window
     * is set smaller to stay on one row. At 1280x720 and scale 1 both rows fit, no note.
     */
    @Test
    void aSlideLeavesTheSceneItsShareByCuttingFormulaRowsNotTheType() {
        HudLayout hall = new HudLayout(MONO);
        float scale = 1.5f * 1.25f;
        String title = "10.  Collisions      4/22 Collision Resolution: the three phases";
        hall.layOutPresentation(1920, 1080, scale, title, SLIDE, READOUT, "F8  full HUD", "");
        assertEquals(1, hall.getBodyLines(), "the second formula row hidden");
        assertEquals(2, hall.getBodyLinesNeeded());
        assertEquals(HudLayout.PRESENT_SIZE * scale, hall.getBodySize(), 1e-3f,
                "the formulas keep the size asked for");
        // The scene reaches up to the formulas' band: its height is the window's less the
        // margin, the title, one row and the band's spaces, within a pixel's rounding.
        assertTrue(hall.getScene().getHeight() >= HudLayout.PRESENT_SCENE_SHARE * 1080f - 1f,
                hall.getScene().toString());
        assertEquals("F8  full HUD" + HudLayout.FORMULAS_CUT_NOTE, hall.getFooterText());
        assertEquals(1, HudLayout.countLines(hall.getTitleText()), hall.getTitleText());
        assertTrue(hall.getTitleSize() >= HudLayout.MIN_PRESENT_TITLE_FRACTION
                * HudLayout.PRESENT_SIZE * scale - 1e-3f);
        assertTrue(hall.getTitleSize() < HudLayout.PRESENT_SIZE * scale, "set smaller");

        HudLayout desk = new HudLayout(MONO);
        desk.layOutPresentation(1280, 720, 1f, "3.  Drag", SLIDE, READOUT, "F8  full HUD", "");
        assertEquals(2, desk.getBodyLines());
        assertEquals("F8  full HUD", desk.getFooterText());
        assertEquals(HudLayout.PRESENT_SIZE, desk.getTitleSize(), 1e-3f);
    }

    @ParameterizedTest
    @CsvSource({"1, 1", "30, 20", "120, 90", "199, 149"})
    void belowTheSmallestWindowTheSceneStillGetsAPlaceInsideIt(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        layout.setPanelWidth(320f);
        layout.setGraphSize(360f, 200f);
        layout.layOut(width, height, HudScale.MIN_SCALE, "3.  Drag", lines(12), FOOTER,
                help(40));
        ScreenRect scene = layout.getScene();
        assertFalse(scene.isEmpty(), scene.toString());
        assertTrue(layout.getWindow().contains(scene), scene.toString());
    }

    @Test
    void helpOnTheSmallestWindowKeepsTheColumnsThatFitAndSaysMoreIsHidden() {
        HudLayout layout = new HudLayout(MONO);
        String help = help(80);
        layout.layOut(HudLayout.MIN_WIDTH, HudLayout.MIN_HEIGHT, HudScale.MIN_SCALE,
                "5.  HelloAiming", BODY, FOOTER, help);
        List<ScreenRect> columns = layout.getHelpColumns();
        for (ScreenRect column : columns) {
            assertTrue(layout.getHelpPanel().contains(column), column.toString());
        }
        List<String> texts = layout.getHelpColumnTexts();
        assertTrue(texts.get(texts.size() - 1).endsWith("\n" + HudLayout.HELP_CUT_LINE),
                texts.get(texts.size() - 1));
        assertTrue(texts.get(0).startsWith("Demo - keys\n   F  -  fire"), texts.get(0));
    }

    /**
     * Issue 36: a small window's frames took about a second each under load, because every
     * layout (a resize, a body that grew a line, a new footer) flowed the help again at
     * every size from the largest down, in up to five column counts, shown or not. The help
     * is flowed when first asked for after a layout, again only when its text, its panel or
     * the scale changed, and a size whose own lines cannot fit the most columns is passed
     * over without a flow; the columns come out as a fresh layout's.
     */
    @Test
    void theHelpIsFlowedWhenAskedForAndAgainOnlyWhenItsTextPanelOrScaleChanged() {
        HudLayout layout = new HudLayout(MONO);
        String help = help(80);
        float scale = HudLayout.scaleFor(1280, 720);
        layout.layOut(1280, 720, scale, "5.  HelloAiming", BODY, FOOTER, help);
        layout.layOut(1920, 1080, scale, "5.  HelloAiming", BODY, FOOTER, help);
        assertEquals(0, layout.countHelpFlows(), "laid out twice, the help never asked for");
        layout.layOut(1280, 720, scale, "5.  HelloAiming", BODY, FOOTER, help);
        layout.getHelpColumns();
        int flows = layout.countHelpFlows();
        assertTrue(flows >= 1, flows + " flows");
        layout.layOut(1280, 720, scale, "5.  HelloAiming", BODY + "\none more line", "F8  only",
                help);
        layout.getHelpColumns();
        assertEquals(flows, layout.countHelpFlows(), "a new body and footer, the same help");
        HudLayout fresh = new HudLayout(MONO);
        fresh.layOut(1280, 720, scale, "5.  HelloAiming", BODY + "\none more line", "F8  only",
                help);
        assertEquals(fresh.getHelpColumnTexts(), layout.getHelpColumnTexts());
        assertEquals(fresh.getHelpColumns().toString(), layout.getHelpColumns().toString());
        assertEquals(fresh.getHelpSize(), layout.getHelpSize(), 0f);
        layout.layOut(1280, 720, scale, "5.  HelloAiming", BODY, FOOTER, help(81));
        layout.getHelpColumnTexts();
        assertTrue(layout.countHelpFlows() > flows, "a new help is flowed");
        int before = layout.countHelpFlows();
        layout.layOut(1281, 720, scale, "5.  HelloAiming", BODY, FOOTER, help(81));
        layout.getHelpPanel();
        assertTrue(layout.countHelpFlows() > before, "a new width is flowed");
    }

    @Test
    void theSmallestWindowFlowsItsHelpAFewTimesNotAtEverySize() {
        HudLayout layout = new HudLayout(MONO);
        layout.layOut(HudLayout.MIN_WIDTH, HudLayout.MIN_HEIGHT, HudScale.MIN_SCALE,
                "5.  HelloAiming", BODY, FOOTER, help(80));
        layout.getHelpColumns();
        // 93 help lines against a panel of a few lines: no size down to the smallest can
        // hold them in five columns, so the one flow left is the smallest size's cut (it
        // was every size from 21 px down to 11 px by 2 % in one to five columns: 165).
        assertEquals(1, layout.countHelpFlows());
    }

    @Test
    void firstLinesKeepsWholeLinesFromTheTop() {
        assertEquals("a\nb", HudLayout.firstLines("a\nb\nc", 2).toString());
        assertEquals("a\nb\nc", HudLayout.firstLines("a\nb\nc", 3).toString());
        assertEquals("a\nb\nc", HudLayout.firstLines("a\nb\nc", 9).toString());
        assertEquals("", HudLayout.firstLines("a\nb", 0).toString());
        assertEquals(3, HudLayout.countLines("a\nb\nc"));
    }

    @Test
    void wrapBreaksAtSpacesAndIndentsContinuations() {
        HudLayout layout = new HudLayout(MONO);
        // 10 px per character at size 20: 12 characters fit in 120 px.
        String wrapped = layout.wrap("alpha beta gamma delta", 20f, 120f);
        assertEquals("alpha beta\n    gamma\n    delta", wrapped);
        assertEquals("short", layout.wrap("short", 20f, 120f));
        // A word longer than the width stays whole on its own line.
        assertEquals("abcdefghijklmnop\n    q", layout.wrap("abcdefghijklmnop q", 20f, 120f));
    }

    @Test
    void wrapKeepsANumberWithItsUnit() {
        // Issue 29 §3: a presentation readout ended "quadratic x = 10.57" with "m" alone on the
        // next line. 12 characters fit in 120 px at size 20: "ab x = 10.57" fits, " m" does
        // not, so the number moves down with its unit.
        HudLayout layout = new HudLayout(MONO);
        assertEquals("ab x =\n    10.57 m", layout.wrap("ab x = 10.57 m", 20f, 120f));
        assertEquals("v =\n    3.5 m/s²", layout.wrap("v = 3.5 m/s²", 20f, 90f));
        // A word that is not a unit still breaks after a number.
        assertEquals("in 10.57\n    seconds", layout.wrap("in 10.57 seconds", 20f, 120f));
        // A number and unit wider than the line stay whole on their own line.
        assertEquals("x =\n    123456789 m", layout.wrap("x = 123456789 m", 20f, 80f));
    }

    @Test
    void wrapMovesAGroupDownWholeAtItsThreeSpaceGap() {
        // Issue 29 §3: the targets slide's "2 collision: impulse j, e = 0.6" was split before
        // its last words. 30 characters fit in 300 px at size 20.
        HudLayout layout = new HudLayout(MONO);
        assertEquals("1 prologue: ignore\n    2 collision: impulse j, e",
                layout.wrap("1 prologue: ignore   2 collision: impulse j, e", 20f, 300f));
        // Where the group would not fit on its own line either, the break stays at the word.
        assertEquals("a   bc\n    defghijklmnopqrstuvwxyz12",
                layout.wrap("a   bc defghijklmnopqrstuvwxyz12", 20f, 300f));
        // Two spaces are no group gap; a line without a gap breaks at its words as before.
        assertEquals("alpha  beta\n    gamma", layout.wrap("alpha  beta gamma", 20f, 120f));
    }

    @Test
    void scaleIsOneAtTheReferenceWindowAndGrowsWithIt() {
        assertEquals(1f, HudLayout.scaleFor(1280, 720), 0f);
        assertEquals(1.5f, HudLayout.scaleFor(1920, 1080), 0f);
        assertEquals(3f, HudLayout.scaleFor(3840, 2160), 0f);
        assertEquals(0.8f, HudLayout.scaleFor(1024, 768), 1e-6f);
        assertEquals(HudLayout.MIN_SCALE, HudLayout.scaleFor(320, 200), 0f);
    }

    /** A body of numbered lines, each ending in a newline but the last. */
    @Test
    void aWindowTooSmallForTheFactorAskedNamesItAndTheOneItGot() {
        // Issue 19: at --ui-scale 2 on 640x360 the footer said "window too small" and not
        // which factor was reduced. HudScale shrinks the scale that suits the window (0.75
        // there) to 0.5, then doubles it: x1.0 of the 0.75, shown as x1.3 of it.
        HudLayout layout = new HudLayout(MONO);
        layout.setUserFactor(2f);
        layout.layOut(640, 360, 2f * HudScale.MIN_SCALE, "3.  Drag", lines(30), FOOTER,
                help(40));
        assertTrue(layout.isTooSmall());
        assertEquals("text x2.0 reduced to x1.3: window too small (640x360), HUD lines hidden",
                layout.getFooterText().replace("\n    ", " "));
        // A factor the window gave in full is not called reduced.
        layout.setUserFactor(1f);
        layout.layOut(640, 360, HudLayout.scaleFor(640, 360), "3.  Drag", lines(30), FOOTER,
                help(40));
        assertEquals("window too small (640x360): HUD lines hidden",
                layout.getFooterText().replace("\n    ", " "));
    }

    @ParameterizedTest
    @CsvSource({"1280, 720", "1024, 768", "1920, 1080"})
    void presentationGivesTheSceneThreeQuartersAndTextTwiceTheBodys(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        layout.setPanelWidth(320f);
        float scale = HudLayout.scaleFor(width, height);
        layout.layOutPresentation(width, height, scale, "3.  Drag", SLIDE, READOUT,
                "F8  full HUD", help(40));
        assertTrue(layout.isPresenting());
        assertFalse(layout.isTooSmall());
        ScreenRect scene = layout.getScene();
        // Three quarters of the window's area, from the rectangle itself (MONO's lines are
        // 1.2 of the size, a little higher than the real font's 56/48).
        assertTrue(scene.getWidth() * scene.getHeight() >= 0.75f * width * height,
                scene + " of " + width + "x" + height);
        // No side panel while presenting: the scene has the window's whole width.
        assertEquals(width, scene.getWidth(), 0f);
        assertTrue(layout.getSidePanel().isEmpty());
        // Twice the full HUD's body at the same scale, title, formulas and readout alike.
        float body = HudLayout.BODY_SIZE * scale;
        assertTrue(layout.getBodySize() >= 2f * body, layout.getBodySize() + " px");
        assertTrue(layout.getTitleSize() >= 2f * body, layout.getTitleSize() + " px");
        assertEquals(2, layout.getBodyLines());
        assertEquals(1, layout.getReadoutLines());
        assertEquals(layout.getBodyLines() * MONO.lineHeight(layout.getBodySize()),
                layout.getBody().getHeight(), 1e-3f);
        assertBlocksApartInside(layout);
        // The readout and the footer are drawn on the scene's ground, below its floor.
        assertTrue(layout.getReadout().getTop() <= layout.getSceneFloor());
        assertTrue(layout.getFooter().getTop() <= layout.getReadout().getY());
        assertFalse(scene.intersects(layout.getBody()), scene + " over the formulas");
    }

    @ParameterizedTest
    @CsvSource({"200, 150", "320, 240", "640, 360", "3840, 2160"})
    void presentationOnAnyWindowKeepsItsTextApartAndInside(int width, int height) {
        HudLayout layout = new HudLayout(MONO);
        layout.layOutPresentation(width, height, HudScale.MIN_SCALE, "3.  Drag", SLIDE,
                READOUT, "F8  full HUD", help(40));
        assertBlocksApartInside(layout);
        assertTrue(layout.getScene().getHeight() >= HudLayout.MIN_SCENE_SHARE * height,
                layout.getScene().toString());
        if (layout.isTooSmall()) {
            // The readout goes last of the slide's lines: the second formula line first.
            assertTrue(layout.getBodyLines() < 2, layout.getBodyLines() + " formula lines");
            assertTrue(layout.getFooterText().replace("\n    ", " ")
                    .contains("window too small (" + width + "x" + height + ")"));
        }
    }

    @Test
    void theFullHudAfterPresentationHasNoReadoutAndItsOwnSizes() {
        HudLayout layout = new HudLayout(MONO);
        layout.layOutPresentation(1280, 720, 1f, "3.  Drag", SLIDE, READOUT, "F8  full HUD",
                help(40));
        layout.layOut(1280, 720, 1f, "3.  Drag", BODY, FOOTER, help(40));
        assertFalse(layout.isPresenting());
        assertTrue(layout.getReadout().isEmpty());
        assertEquals(0, layout.getReadoutLines());
        assertEquals(HudLayout.BODY_SIZE, layout.getBodySize(), 0f);
        assertEquals(HudLayout.TITLE_SIZE, layout.getTitleSize(), 0f);
    }

    /** The title, formulas, readout and footer: none over another, each inside the window. */
    private static void assertBlocksApartInside(HudLayout layout) {
        List<ScreenRect> blocks = List.of(layout.getTitle(), layout.getBody(),
                layout.getReadout(), layout.getFooter());
        for (int i = 0; i < blocks.size(); ++i) {
            if (blocks.get(i).isEmpty()) {
                continue;
            }
            assertTrue(layout.getWindow().contains(blocks.get(i)), i + " " + blocks.get(i));
            for (int j = 0; j < i; ++j) {
                assertFalse(blocks.get(i).intersects(blocks.get(j)), i + " over " + j);
            }
        }
        assertTrue(layout.getWindow().contains(layout.getScene()));
    }

    /** A factor as the footer prints it, with one decimal. */
    private static String oneDecimal(float factor) {
        long tenths = Math.round(10.0 * factor);
        return tenths / 10 + "." + tenths % 10;
    }

    private static String lines(int count) {
        StringBuilder text = new StringBuilder();
        for (int i = 1; i <= count; ++i) {
            text.append("line ").append(i).append(i < count ? "\n" : "");
        }
        return text.toString();
    }

    /**
     * The energy ledger's strip (issue 32) takes its own place down the scene's right edge,
     * in the full HUD and presenting, with the side panel and the graph or without, from the
     * smallest window to 4K: inside the window, never of negative size, clear of every text,
     * the panel and the graph, and the scene stays left of it (no body flies under it).
     */
    @ParameterizedTest
    @CsvSource({"200, 150", "640, 360", "1280, 720", "1920, 1080", "3840, 2160", "150, 100"})
    void theLedgerStripKeepsClearOfTheTextsAndTheSceneAtEverySize(int width, int height) {
        for (int mode = 0; mode < 4; ++mode) {
            boolean presenting = mode % 2 == 1;
            boolean extras = mode >= 2;
            HudLayout layout = new HudLayout(MONO);
            layout.setPanelWidth(extras ? 320f : 0f);
            layout.setGraphSize(extras ? 360f : 0f, extras ? 200f : 0f);
            layout.setLedgerSize(380f, 180f);
            float scale = HudLayout.scaleFor(width, height);
            if (presenting) {
                layout.layOutPresentation(width, height, scale, "9.  Bounce", SLIDE, READOUT,
                        "F8  full HUD", help(40));
            } else {
                layout.layOut(width, height, scale, "9.  Bounce", BODY, FOOTER, help(40));
            }
            String where = width + "x" + height + (presenting ? " presenting" : "")
                    + (extras ? " with panel and graph" : "");
            ScreenRect ledger = layout.getLedger();
            assertTrue(ledger.getWidth() >= 0f && ledger.getHeight() >= 0f,
                    ledger + " " + where);
            if (ledger.isEmpty()) {
                // no room for it: the scene keeps the whole width left of the panel
                assertTrue(width < 640, "the strip went at " + where);
                continue;
            }
            assertTrue(layout.getWindow().contains(ledger), ledger + " " + where);
            for (ScreenRect other : List.of(layout.getTitle(), layout.getBody(),
                    layout.getWarning(), layout.getFooter(), layout.getReadout(),
                    layout.getSidePanel(), layout.getGraph())) {
                assertFalse(other.intersects(ledger), other + " over the strip " + ledger
                        + " " + where);
            }
            assertTrue(layout.getScene().getRight() <= ledger.getX(),
                    "the scene " + layout.getScene() + " runs under the strip " + ledger
                    + " " + where);
            if (width >= 1280 && !extras) {
                // on a lecture's window it has the room it asked for, at the HUD's scale
                assertEquals(380f * layout.getScale() - layout.getMargin(), ledger.getWidth(),
                        1e-3f, where);
            }
        }
    }

    /** A help text like the demos': the demo's section first, then sections of 8 keys. */
    private static String help(int keys) {
        StringBuilder text = new StringBuilder("Demo - keys\n   F  -  fire\n   Up  -  vx + 1\n");
        for (int i = 0; i < keys; ++i) {
            if (i % 8 == 0) {
                text.append("\nSection ").append(i / 8).append('\n');
            }
            text.append("   K").append(i).append("  -  a key that does thing number ")
                    .append(i).append('\n');
        }
        return text.toString();
    }

    /**
     * The scene reaches from the window's bottom up to the warning band's top, below the title
     * and the body; the warning band is drawn over its sky and the footer on its ground,
     * below the floor the scene's content keeps above.
     */
    private static void assertSceneUnderTheTextAndOverTheFooter(HudLayout layout) {
        ScreenRect scene = layout.getScene();
        assertTrue(layout.getWindow().contains(scene), scene.toString());
        assertFalse(scene.intersects(layout.getTitle()), scene + " over the title");
        assertFalse(scene.intersects(layout.getBody()), scene + " over the body");
        assertEquals(0f, scene.getY(), 0f);
        assertEquals(layout.getWarning().getTop(), scene.getTop(), 1e-3f);
        assertTrue(layout.getFooter().getTop() <= layout.getSceneFloor(),
                layout.getFooter() + " above the floor " + layout.getSceneFloor());
    }
}
