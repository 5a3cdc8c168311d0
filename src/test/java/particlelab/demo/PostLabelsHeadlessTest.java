package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.ClipResponseDemo;
import particlelab.physics.SimulationClock;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.Trail;

/**
 * A post's name stays readable while the shot flies: in the clip demo, at the three window
 * sizes the lecture is shown at and in presentation mode, neither ledge's name is hidden, no
 * trail (its ribbon's width included) is drawn over it at any frame of the shots the keys
 * allow (slow and fast, level and at the steepest climb, both clips) while it is shown, unless
 * it lies on its plate, which hides the trail under it (the scene's rule for a post's name
 * since the plates, as {@link OverlapProbe} checks), no sphere rests on it, and it touches no
 * post. A sphere passing over a name hides it until it has moved on.
 * The "ledge" name stood on the post's top, where the target rests and its trail starts.
 */
class PostLabelsHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{640, 360}, {1280, 720}, {3840, 2160}};
    /** The shot runs this long, checked every frame: impact, fall, bounces and rest. */
    private static final int FRAMES = 300;
    /** The shots checked: speed (m/s), climb (deg), clip index. */
    private static final float[][] SHOTS = {{12f, 0f, 0f}, {4f, 0f, 0f}, {40f, 0f, 1f},
        {12f, 30f, 0f}, {4f, 30f, 1f}, {40f, 30f, 0f}};
    /**
     * A sphere slower than this (in m/s) stays over what it covers: the target resting on its
     * ledge, a body come to rest on the ground. A faster one passes in a few frames (the
     * slowest shot's target grazes the name's corner as it lands, in a 640x360 window in
     * presentation mode).
     */
    private static final float RESTING_SPEED = 0.5f;
    private static HeadlessHarness harness;
    private static ClipResponseDemo clip;

    @BeforeAll
    static void startApp() throws Exception {
        clip = new ClipResponseDemo();
        harness = HeadlessHarness.start(List.of(clip));
    }

    @AfterAll
    static void stopApp() {
        harness.close();
    }

    @Test
    void nothingIsDrawnOverTheLedgesNames() throws Exception {
        List<String> problems = new ArrayList<>();
        for (boolean presenting : new boolean[] {false, true}) {
            for (int[] window : WINDOWS) {
                for (float[] shot : SHOTS) {
                    problems.addAll(harness.call(() -> run(window[0], window[1], presenting,
                            shot)));
                }
            }
        }
        harness.call(() -> {
            clip.getDemoHud().setPresenting(false);
            clip.getParameters().set("speed", 12f);
            clip.getParameters().set("angle", 0f);
            clip.getParameters().set("clip", 0f);
            clip.getDemoHud().layOut(1280, 720);
            return true;
        });
        assertEquals(List.of(), problems.subList(0, Math.min(10, problems.size())),
                problems.size() + " problems");
    }

    /** Fire one shot at a window size and check the posts' names every frame. */
    private static List<String> run(int width, int height, boolean presenting, float[] shot) {
        clip.getDemoHud().setPresenting(presenting);
        clip.getDemoHud().layOut(width, height);
        clip.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        clip.getClock().setPaused(false);
        clip.getParameters().set("speed", shot[0]);
        clip.getParameters().set("angle", shot[1]);
        clip.getParameters().set("clip", shot[2]);
        clip.restart();
        String where = width + "x" + height + (presenting ? " presenting" : "") + ", "
                + shot[0] + " m/s at " + shot[1] + " deg, clip " + shot[2] + ", frame ";
        List<String> problems = new ArrayList<>();
        for (int frame = 0; frame < FRAMES; ++frame) {
            clip.update(H);
            // One problem per shot is enough to see it; the rest would repeat it.
            if (problems.isEmpty()) {
                problems.addAll(check(where + frame));
            }
        }
        return problems;
    }

    /** Each post's name is shown, and covers no post, no resting sphere and no trail. */
    private static List<String> check(String when) {
        List<String> problems = new ArrayList<>();
        PlaneView plane = clip.getPlaneView();
        List<ScreenRect> names = clip.getWindow().copyPostLabelRects(new ArrayList<>());
        List<ScreenRect> posts = clip.getWindow().copyPostRects(new ArrayList<>());
        List<DemoParticle> particles = clip.getParticles();
        Node sceneNode = clip.getView(particles.get(0)).getNode().getParent();
        List<ScreenRect> shown = clip.getWindow().copyTextRects(new ArrayList<>());
        Vector3f point = new Vector3f();
        for (int n = 0; n < names.size(); ++n) {
            ScreenRect name = names.get(n);
            if (name.isEmpty()) {
                problems.add(when + ": post name " + n + " hidden");
                continue;
            }
            for (int p = 0; p < posts.size(); ++p) {
                if (name.intersects(posts.get(p))) {
                    problems.add(when + ": post name " + n + " " + name + " on post " + p + " "
                            + posts.get(p));
                }
            }
            for (int j = 0; j < particles.size(); ++j) {
                DemoParticle particle = particles.get(j);
                if (particle.isParked()) {
                    continue;
                }
                float radius = clip.getView(particle).getRadius() * plane.getPixelsPerMetre();
                Vector3f centre = particle.getParticle().position;
                // The sphere is drawn as a disc: the rectangle's point nearest its centre.
                float x = plane.screenX(centre.x);
                float y = plane.screenY(centre.y);
                float dx = x - Math.max(name.getX(), Math.min(x, name.getRight()));
                float dy = y - Math.max(name.getY(), Math.min(y, name.getTop()));
                // A ball passing over a sign is not the sign hidden; one resting there is.
                boolean resting = particle.getParticle().velocity.length() < RESTING_SPEED;
                if (resting && dx * dx + dy * dy < radius * radius) {
                    problems.add(when + ": post name " + n + " " + name + " under the sphere of "
                            + particle.getLabel());
                }
                // A name hidden while a sphere passes over it (the scene shows it again when
                // the sphere has moved on) is not drawn, so nothing is drawn over it; on its
                // plate it is drawn over the trail, which the plate hides (OverlapProbe's rule).
                Spatial plate = sceneNode.getChild(DemoScene.POST_PLATE + n);
                if (!isShown(name, shown)
                        || plate != null && plate.getCullHint() != Spatial.CullHint.Always) {
                    continue;
                }
                // The ribbon is a quarter of the radius wide on each side of its points
                // (ParticleView): a point that near the name draws over it.
                float halfWidth = 0.25f * radius;
                ScreenRect reach = new ScreenRect(name.getX() - halfWidth,
                        name.getY() - halfWidth, name.getWidth() + 2f * halfWidth,
                        name.getHeight() + 2f * halfWidth);
                Trail trail = clip.getView(particle).getTrail();
                for (int age = 0; age < trail.size(); ++age) {
                    trail.copyPoint(age, point);
                    if (reach.contains(plane.screenX(point.x), plane.screenY(point.y))) {
                        problems.add(when + ": post name " + n + " " + name
                                + " under the trail of " + particle.getLabel());
                        break;
                    }
                }
            }
        }
        return problems;
    }

    /** Test whether a rectangle is one of the scene's texts shown (the same place and size). */
    private static boolean isShown(ScreenRect rect, List<ScreenRect> shown) {
        for (ScreenRect text : shown) {
            if (text.getX() == rect.getX() && text.getY() == rect.getY()
                    && text.getWidth() == rect.getWidth()
                    && text.getHeight() == rect.getHeight()) {
                return true;
            }
        }
        return false;
    }
}
