package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.font.BitmapCharacterSet;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.HelloAimingDemo;
import particlelab.physics.SimulationClock;
import particlelab.view.HudFont;
import particlelab.view.HudText;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.Trail;

/**
 * Every catalogue demo laid out for windows of four sizes in a real headless jME application,
 * with the real font's measures: no text covers another, every text is inside the window, the
 * particles' labels cover no other sphere and no trail, the help fits with the demo's own keys
 * first, and every character any text prints is in the font.
 */
class ScreenLayoutHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{1024, 768}, {1280, 720}, {1920, 1080},
        {3840, 2160}};
    /** The demos run this long, sampled every few frames: launch, flight and landing. */
    private static final int FRAMES = 480;
    private static final int SAMPLE_EVERY = 6;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void noTextCoversAnotherOrLeavesTheWindowAtAnySize() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : demos()) {
            for (int[] window : WINDOWS) {
                problems.addAll(harness.call(() -> runAndCheck(demo, window[0], window[1])));
            }
            harness.call(() -> {
                demo.getDemoHud().layOut(1280, 720);
                return true;
            });
        }
        assertEquals(List.of(), problems.subList(0, Math.min(10, problems.size())),
                problems.size() + " problems");
    }

    @Test
    void helpFitsEveryWindowWithTheDemosOwnKeysFirst() throws Exception {
        for (DemoState demo : demos()) {
            for (int[] window : WINDOWS) {
                List<String> problems = harness.call(() -> {
                    demo.getDemoHud().layOut(window[0], window[1]);
                    demo.getWindow().getHud().setHelpVisible(true);
                    List<String> found = check(demo, window[0], window[1], "help");
                    List<String> columns = demo.getWindow().getHud().getHelpColumnTexts();
                    // The first section is the demo's own keys: it opens the first column.
                    String help = demo.getKeys().getHelpText();
                    String ownSection = help.substring(0, help.indexOf("\n\n"));
                    if (!columns.get(0).replaceAll("\\s+", " ")
                            .startsWith(ownSection.replaceAll("\\s+", " "))) {
                        found.add(demo.getTitle() + ": the help does not open with "
                                + ownSection);
                    }
                    // Lines are wrapped to their column: compare with the spaces folded.
                    String all = String.join(" ", columns).replaceAll("\\s+", " ");
                    for (String line : demo.getKeys().getHelpText().split("\n")) {
                        if (!all.contains(line.replaceAll("\\s+", " ").strip())) {
                            found.add(demo.getTitle() + ": help column lacks " + line);
                        }
                    }
                    demo.getWindow().getHud().setHelpVisible(false);
                    demo.getDemoHud().layOut(1280, 720);
                    return found;
                });
                assertEquals(List.of(), problems, window[0] + "x" + window[1]);
            }
        }
    }

    @Test
    void theHighestArcTheKeysAllowStaysInTheSceneAreaAtEverySize() throws Exception {
        HelloAimingDemo aiming = (HelloAimingDemo) demos().get(DemoCatalog.indexOf("aiming"));
        for (int[] window : WINDOWS) {
            List<String> problems = harness.call(() -> {
                List<String> found = new ArrayList<>();
                aiming.getDemoHud().layOut(window[0], window[1]);
                for (HelloAimingDemo.Aim aim : HelloAimingDemo.Aim.values()) {
                    aiming.setAim(aim);
                    aiming.setHorizontalSpeed(HelloAimingDemo.MIN_VX);
                    aiming.fire();
                    // The lowest vx flies S/vx = 8.3 s: 600 frames see it land.
                    DemoParticle bullet = aiming.getBullet(aim);
                    ScreenRect area = aiming.getWindow().getHud().getLayout().getScene();
                    for (int frame = 0; frame < 600; ++frame) {
                        aiming.update(H);
                        PlaneView plane = aiming.getWindow().getPlaneView();
                        Vector3f p = bullet.getParticle().position;
                        float radius = aiming.getWindow().getView(bullet).getRadius()
                                * plane.getPixelsPerMetre();
                        ScreenRect sphere = new ScreenRect(plane.screenX(p.x) - radius,
                                plane.screenY(p.y) - radius, 2f * radius, 2f * radius);
                        if (!area.contains(sphere)) {
                            found.add(window[0] + "x" + window[1] + " " + aim + " frame "
                                    + frame + ": bullet " + sphere + " leaves " + area);
                            break;
                        }
                    }
                    if (!bullet.hasLanded()) {
                        found.add(aim + ": the shot did not land");
                    }
                }
                aiming.setHorizontalSpeed(HelloAimingDemo.DEFAULT_VX);
                aiming.setBothAims();
                aiming.getDemoHud().layOut(1280, 720);
                return found;
            });
            assertEquals(List.of(), problems);
        }
    }

    @Test
    void everyCharacterShownIsInTheFont() throws Exception {
        for (DemoState demo : demos()) {
            List<String> missing = harness.call(() -> {
                List<String> found = new ArrayList<>();
                demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
                demo.restart();
                // Walk through the states that add text: running, raw tpf with a hitch
                // (warnings), paused; and the help.
                collectMissing(demo, found);
                demo.getClock().toggleMode();
                demo.getRun().injectHitch();
                for (int frame = 0; frame < 30; ++frame) {
                    demo.update(H);
                    collectMissing(demo, found);
                }
                demo.getClock().toggleMode();
                demo.getClock().setPaused(true);
                demo.update(H);
                collectMissing(demo, found);
                demo.getClock().setPaused(false);
                return found;
            });
            assertEquals(List.of(), missing, demo.getTitle());
        }
    }

    /** Run a demo for a window size and check its texts every few frames. */
    private static List<String> runAndCheck(DemoState demo, int width, int height) {
        demo.getDemoHud().layOut(width, height);
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.restart();
        List<String> problems = new ArrayList<>();
        for (int frame = 0; frame < FRAMES; ++frame) {
            demo.update(H);
            if (frame % SAMPLE_EVERY == 0) {
                problems.addAll(check(demo, width, height, "frame " + frame));
                problems.addAll(checkParticleLabels(demo, width, height, frame));
            }
        }
        return problems;
    }

    /** No two texts overlap, and all are inside the window. */
    private static List<String> check(DemoState demo, int width, int height, String when) {
        return ScreenChecks.textsApartInside(demo.getWindow().copyTextRects(new ArrayList<>()),
                width, height, demo.getTitle() + " " + width + "x" + height + " " + when);
    }

    /** A particle's label covers no other sphere, no point of any trail and no post. */
    private static List<String> checkParticleLabels(DemoState demo, int width, int height,
            int frame) {
        List<String> problems = new ArrayList<>();
        PlaneView plane = demo.getWindow().getPlaneView();
        List<DemoParticle> particles = demo.getParticles();
        List<ScreenRect> posts = demo.getWindow().copyPostRects(new ArrayList<>());
        Vector3f point = new Vector3f();
        for (int i = 0; i < particles.size(); ++i) {
            ScreenRect label = demo.getWindow().getView(particles.get(i)).getLabelRect();
            for (int p = 0; p < posts.size(); ++p) {
                if (label.intersects(posts.get(p))) {
                    problems.add(demo.getTitle() + " " + width + "x" + height + " frame "
                            + frame + ": label of " + particles.get(i).getLabel()
                            + " covers post " + p + " " + posts.get(p));
                }
            }
            for (int j = 0; j < particles.size(); ++j) {
                Vector3f other = particles.get(j).getParticle().position;
                float radius = demo.getWindow().getView(particles.get(j)).getRadius()
                        * plane.getPixelsPerMetre();
                ScreenRect sphere = new ScreenRect(plane.screenX(other.x) - radius,
                        plane.screenY(other.y) - radius, 2f * radius, 2f * radius);
                if (j != i && label.intersects(sphere)) {
                    problems.add(demo.getTitle() + " " + width + "x" + height + " frame "
                            + frame + ": label of " + particles.get(i).getLabel()
                            + " covers the sphere of " + particles.get(j).getLabel());
                }
                Trail trail = demo.getWindow().getView(particles.get(j)).getTrail();
                // A label on its plate (no free slot) hides the trail under it.
                boolean plated = demo.getWindow().getView(particles.get(i)).isLabelPlated();
                for (int age = 0; age < trail.size() && !plated; ++age) {
                    trail.copyPoint(age, point);
                    if (label.contains(plane.screenX(point.x), plane.screenY(point.y))) {
                        problems.add(demo.getTitle() + " " + width + "x" + height + " frame "
                                + frame + ": label of " + particles.get(i).getLabel()
                                + " covers the trail of " + particles.get(j).getLabel());
                        break;
                    }
                }
            }
        }
        return problems;
    }

    private static void collectMissing(DemoState demo, List<String> found) {
        List<String> texts = new ArrayList<>();
        texts.add(demo.getWindow().getHud().getTitleText());
        texts.add(demo.getWindow().getHud().getBodyText());
        texts.add(demo.getWindow().getHud().getWarningText());
        texts.add(demo.getWindow().getHud().getFooterText());
        texts.addAll(demo.getWindow().getHud().getHelpColumnTexts());
        List<BitmapText> shown = new ArrayList<>();
        collectTexts(demo.getSceneNode(), BitmapText.class, shown);
        collectTexts(demo.getWindow().getHud().getNode(), BitmapText.class, shown);
        for (BitmapText text : shown) {
            texts.add(text.getText());
            if (!HudFont.BASE_NAME.equals(fontName(text.getFont()))) {
                found.add("text '" + text.getText() + "' is not in " + HudFont.ASSET);
            }
        }
        List<HudText> hudTexts = new ArrayList<>();
        collectTexts(demo.getSceneNode(), HudText.class, hudTexts);
        collectTexts(demo.getWindow().getHud().getNode(), HudText.class, hudTexts);
        for (HudText text : hudTexts) {
            texts.add(text.getText());
            if (!HudFont.BASE_NAME.equals(fontName(text.getFont()))) {
                found.add("text '" + text.getText() + "' is not in " + HudFont.ASSET);
            }
        }
        BitmapCharacterSet font = hudTexts.get(0).getFont().getCharSet();
        for (String text : texts) {
            for (int i = 0; i < text.length(); ++i) {
                char c = text.charAt(i);
                if (c != '\n' && font.getCharacter(c) == null && !found.contains("" + c)) {
                    found.add("" + c);
                }
            }
        }
    }

    private static String fontName(BitmapFont font) {
        String key = font.getPage(0).getTextureParam("ColorMap").getTextureValue()
                .getKey().getName();
        String file = key.substring(key.lastIndexOf('/') + 1);
        return file.substring(0, file.lastIndexOf('.'));
    }

    private static <T extends Spatial> void collectTexts(Spatial spatial, Class<T> type,
            List<T> storeResult) {
        if (type.isInstance(spatial)) {
            storeResult.add(type.cast(spatial));
        } else if (spatial instanceof Node) {
            for (Spatial child : ((Node) spatial).getChildren()) {
                collectTexts(child, type, storeResult);
            }
        }
    }

    private static List<DemoState> demos() {
        return harness.app().getSwitcher().getDemos();
    }
}
