package particlelab.demo;

import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.ArrayList;
import java.util.List;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.TargetsDemo;
import particlelab.view.BodyViews;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.Trail;

/**
 * The overlap checks of a laid-out frame, for tests outside this package (the tour's): no two
 * texts cover each other, no text leaves the window, no text covers a sphere shown in the
 * scene, no particle's label covers a post or (unless on its plate) a trail as drawn, and no
 * sphere a viewer sees goes without its label (nor one beyond the scene's side without its
 * label at that side), and two spheres that coincide on the screen (centres closer than
 * {@link ParticleView#JOIN_RADII} radii) share one joined label naming both; from the
 * rectangles the
 * layout itself placed ({@link DemoWindow#copyTextRects}, the particles' label slots, the
 * posts, the collisions demo's impulse labels).
 */
public final class OverlapProbe {

    /** A pixel's rounding: edges this close count as touching, not covering. */
    private static final float PIXEL = 1f;

    private OverlapProbe() {
    }

    /**
     * Open or close a demo's parameter panel, as F2 does, when it is not so already.
     *
     * @param demo the demo (initialised, not null)
     * @param open true for the panel open
     */
    public static void setPanel(DemoState demo, boolean open) {
        if (demo.getParameterControls().isPanelVisible() != open) {
            particlelab.app.HeadlessHarness.press(demo, "F2");
        }
    }

    /**
     * Check a demo's frame as last laid out and updated.
     *
     * @param demo the demo (initialised, laid out, not null)
     * @param width the window's width (pixels)
     * @param height the window's height (pixels)
     * @param where what was laid out, for the messages (not null)
     * @return one line per problem (empty if none)
     */
    public static List<String> check(DemoState demo, int width, int height, String where) {
        List<ScreenRect> texts = demo.getWindow().copyTextRects(new ArrayList<>());
        if (demo instanceof CollisionsDemo) {
            // The impulses' labels, placed by their own layout (CalloutLayout).
            ((CollisionsDemo) demo).copyImpulseLabelRects(texts);
        }
        List<String> problems = new ArrayList<>(ScreenChecks.textsApartInside(texts, width,
                height, where));
        PlaneView plane = demo.getWindow().getPlaneView();
        List<DemoParticle> particles = demo.getParticles();
        List<ScreenRect> posts = demo.getWindow().copyPostRects(new ArrayList<>());
        // The spheres a viewer sees: shown, and inside the scene (above it the HUD's backdrop
        // covers them).
        ScreenRect scene = demo.getWindow().copySceneRect(new ScreenRect());
        List<ScreenRect> spheres = new ArrayList<>();
        List<String> sphereNames = new ArrayList<>();
        List<DemoParticle> sphereParticles = new ArrayList<>();
        ScreenRect panel = demo.getWindow().getHud().getLayout().getSidePanel();
        ScreenRect graph = demo.getWindow().getHud().getLayout().getGraph();
        for (DemoParticle particle : particles) {
            Vector3f centre = particle.getParticle().position;
            float radius = demo.getWindow().getView(particle).getRadius()
                    * plane.getPixelsPerMetre();
            float x = plane.screenX(centre.x);
            float y = plane.screenY(centre.y);
            if (demo.getWindow().getView(particle).getNode().getCullHint()
                    != Spatial.CullHint.Always
                    && scene.contains(x, y)) {
                spheres.add(new ScreenRect(x - radius, y - radius, 2f * radius, 2f * radius));
                sphereNames.add(particle.getLabel());
                sphereParticles.add(particle);
                // A label is never dropped silently: only a sphere under the panel or the
                // graph, which hide it anyway, or one named by a joined label, may go
                // without one.
                if (demo.getWindow().getView(particle).getLabelRect().isEmpty()
                        && !panel.contains(x, y)
                        && !graph.contains(x, y) && !namedByJoinedLabel(demo, particle)) {
                    problems.add(where + ": the sphere of '" + particle.getLabel() + "' at ("
                            + x + ", " + y + ") has no label");
                }
            } else if (demo.getWindow().getView(particle).getNode().getCullHint()
                    != Spatial.CullHint.Always
                    && (x + radius < scene.getX() || x - radius > scene.getRight())
                    && demo.getWindow().getView(particle).getLabelRect().isEmpty()
                    && !particle.getLabel().isEmpty()) {
                // Beyond the scene's side (rolled out of the framed view): its label stands
                // at that side and says where it is.
                problems.add(where + ": the sphere of '" + particle.getLabel() + "' beyond"
                        + " the scene's side at x = " + x + " px has no label at the edge");
            }
        }
        // The targets demo's own spheres beyond its particles (the gun's platform, the
        // targets, the fragments), from its views, not from the label layout's obstacles.
        BodyViews bodies = demo instanceof TargetsDemo
                ? ((TargetsDemo) demo).getBodyViews() : null;
        for (int b = 0; bodies != null && b < bodies.capacity(); ++b) {
            float r = bodies.getDrawnRadius(b) * plane.getPixelsPerMetre();
            Vector3f centre = bodies.copyDrawnCentre(b, new Vector3f());
            float x = plane.screenX(centre.x);
            float y = plane.screenY(centre.y);
            if (r > 0f && scene.contains(x, y)) {
                spheres.add(new ScreenRect(x - r, y - r, 2f * r, 2f * r));
                sphereNames.add("body view " + b);
            }
        }
        problems.addAll(coincidingSpheresShareOneLabel(demo, sphereParticles, where));
        problems.addAll(postNamesClearOfTrails(demo, texts, where));
        for (int t = 0; t < texts.size(); ++t) {
            for (int s = 0; s < spheres.size(); ++s) {
                if (texts.get(t).intersects(spheres.get(s))) {
                    problems.add(where + ": text " + t + " " + texts.get(t)
                            + " covers the sphere of '" + sphereNames.get(s) + "' "
                            + spheres.get(s));
                }
            }
        }
        Vector3f point = new Vector3f();
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            ScreenRect label = demo.getWindow().getView(particle).getLabelRect();
            if (label.isEmpty()) {
                continue;
            }
            String name = where + ": label '" + particle.getLabel() + "' " + label;
            if (particle.getLabel().isEmpty() && !label.isEmpty()) {
                // A nameless body parked out of sight has nothing to say.
                problems.add(name + ": a nameless body has a label");
            }
            for (int p = 0; p < posts.size(); ++p) {
                if (label.intersects(posts.get(p))) {
                    problems.add(name + " covers post " + p + " " + posts.get(p));
                }
            }
            // No trail as drawn (ribbon and step dots) under a label, but where no slot was
            // free: then the label lies on a plate that hides the trail under it.
            for (int o = 0; o < particles.size()
                    && !demo.getWindow().getView(particle).isLabelPlated(); ++o) {
                DemoParticle other = particles.get(o);
                Trail trail = demo.getWindow().getView(other).getTrail();
                float half = trail.getDrawnHalfWidth() * plane.getPixelsPerMetre();
                for (int age = 0; age < trail.size(); ++age) {
                    trail.copyPoint(age, point);
                    float x = plane.screenX(point.x);
                    float y = plane.screenY(point.y);
                    if (x > label.getX() - half + PIXEL && x < label.getRight() + half - PIXEL
                            && y > label.getY() - half + PIXEL
                            && y < label.getTop() + half - PIXEL) {
                        problems.add(name + " covers the trail of '" + other.getLabel()
                                + "' at (" + x + ", " + y + ")");
                        break;
                    }
                }
            }
        }
        return problems;
    }

    /**
     * Two spheres shown that coincide on the screen (centres closer than
     * {@link ParticleView#JOIN_RADII} radii: "slide code" and "ball" in pull's slide lane)
     * have one label between them, and it names both ("ball = slide code").
     */
    private static List<String> coincidingSpheresShareOneLabel(DemoState demo,
            List<DemoParticle> shown, String where) {
        List<String> problems = new ArrayList<>();
        PlaneView plane = demo.getWindow().getPlaneView();
        ScreenRect panel = demo.getWindow().getHud().getLayout().getSidePanel();
        ScreenRect graph = demo.getWindow().getHud().getLayout().getGraph();
        for (int a = 0; a < shown.size(); ++a) {
            for (int b = a + 1; b < shown.size(); ++b) {
                DemoParticle first = shown.get(a);
                DemoParticle second = shown.get(b);
                float radius = demo.getWindow().getView(first).getRadius()
                        * plane.getPixelsPerMetre();
                float ax = plane.screenX(first.getParticle().position.x);
                float ay = plane.screenY(first.getParticle().position.y);
                float dx = plane.screenX(second.getParticle().position.x) - ax;
                float dy = plane.screenY(second.getParticle().position.y) - ay;
                float join = ParticleView.JOIN_RADII * radius;
                if (dx * dx + dy * dy >= join * join || panel.contains(ax, ay)
                        || graph.contains(ax, ay)) {
                    continue;
                }
                ParticleView firstView = demo.getWindow().getView(first);
                ParticleView secondView = demo.getWindow().getView(second);
                String pair = where + ": '" + first.getLabel() + "' and '" + second.getLabel()
                        + "' coincide on the screen";
                if (!firstView.getLabelRect().isEmpty()
                        && !secondView.getLabelRect().isEmpty()) {
                    problems.add(pair + " but have two labels, '"
                            + firstView.getLabel().getText() + "' "
                            + firstView.getLabelRect() + " and '"
                            + secondView.getLabel().getText() + "' "
                            + secondView.getLabelRect());
                } else if (!namedByJoinedLabel(demo, first)
                        || !namedByJoinedLabel(demo, second)) {
                    problems.add(pair + " but no joined label names both");
                }
            }
        }
        return problems;
    }

    /**
     * No post's name shown ("gun", "target  S = 60 m") lies over a trail as drawn, unless on
     * its plate, which hides the trail under it.
     */
    private static List<String> postNamesClearOfTrails(DemoState demo, List<ScreenRect> texts,
            String where) {
        List<String> problems = new ArrayList<>();
        List<DemoParticle> particles = demo.getParticles();
        if (particles.isEmpty()) {
            return problems;
        }
        Node sceneNode = demo.getWindow().getView(particles.get(0)).getNode().getParent();
        List<ScreenRect> names = demo.getWindow().copyPostLabelRects(new ArrayList<>());
        PlaneView plane = demo.getWindow().getPlaneView();
        Vector3f point = new Vector3f();
        for (int n = 0; n < names.size(); ++n) {
            ScreenRect name = names.get(n);
            Spatial plate = sceneNode.getChild(DemoScene.POST_PLATE + n);
            if (!isShown(name, texts) || (plate != null
                    && plate.getCullHint() != Spatial.CullHint.Always)) {
                continue;
            }
            for (DemoParticle other : particles) {
                if (demo.getWindow().getView(other).getNode().getCullHint()
                        == Spatial.CullHint.Always) {
                    continue;
                }
                Trail trail = demo.getWindow().getView(other).getTrail();
                float half = trail.getDrawnHalfWidth() * plane.getPixelsPerMetre();
                for (int age = 0; age < trail.size(); ++age) {
                    trail.copyPoint(age, point);
                    float x = plane.screenX(point.x);
                    float y = plane.screenY(point.y);
                    if (x > name.getX() - half + PIXEL && x < name.getRight() + half - PIXEL
                            && y > name.getY() - half + PIXEL
                            && y < name.getTop() + half - PIXEL) {
                        problems.add(where + ": post name " + n + " " + name
                                + " covers the trail of '" + other.getLabel() + "' at (" + x
                                + ", " + y + ") with no plate");
                        break;
                    }
                }
            }
        }
        return problems;
    }

    /**
     * No label of a sphere above the ground reaches into the ground band (below the ground
     * line, where the distance marks and the footer are): where every slot above covers a
     * trail or a post, the label lies on its plate over the trail instead (issue 29 §3:
     * aiming's joined label "lecture = discrete" fell beside the footer at 1280x720 after the
     * landing).
     *
     * @param demo the demo (laid out and updated, not null)
     * @param where what was laid out, for the messages (not null)
     * @return one line per problem (empty if none)
     */
    public static List<String> labelsAboveTheGround(DemoState demo, String where) {
        List<String> problems = new ArrayList<>();
        PlaneView plane = demo.getWindow().getPlaneView();
        float ground = plane.screenY(0f);
        for (DemoParticle particle : demo.getParticles()) {
            ParticleView view = demo.getWindow().getView(particle);
            ScreenRect label = view.getLabelRect();
            float y = plane.screenY(particle.getParticle().position.y);
            if (!label.isEmpty() && y >= ground && label.getY() < ground - PIXEL) {
                problems.add(where + ": label '" + view.getLabel().getText() + "' " + label
                        + " reaches into the ground band (ground line at y = " + ground
                        + " px)");
            }
        }
        return problems;
    }

    /**
     * No particle's label reaches into the footer band, below the scene's floor
     * ({@code HudLayout.getSceneFloor()}): that band holds the footer's line, not the scene's
     * texts (issue 29 §3: aiming's "discrete" dropped there at the target's foot).
     *
     * @param demo the demo (laid out and updated, not null)
     * @param where what was laid out, for the messages (not null)
     * @return one line per problem (empty if none)
     */
    public static List<String> labelsAboveTheFooterBand(DemoState demo, String where) {
        List<String> problems = new ArrayList<>();
        float floor = demo.getWindow().getHud().getLayout().getSceneFloor();
        for (DemoParticle particle : demo.getParticles()) {
            ParticleView view = demo.getWindow().getView(particle);
            ScreenRect label = view.getLabelRect();
            if (!label.isEmpty() && label.getY() < floor - PIXEL) {
                problems.add(where + ": label '" + view.getLabel().getText() + "' " + label
                        + " reaches into the footer band (scene floor at y = " + floor
                        + " px)");
            }
        }
        return problems;
    }

    /**
     * No impulse label of the collisions demo lies over a trail as drawn (ribbon and step
     * dots): the callouts treat the trails as obstacles, as they do the other labels.
     *
     * @param demo the collisions demo (laid out and updated, not null)
     * @param where what was laid out, for the messages (not null)
     * @return one line per problem (empty if none)
     */
    public static List<String> impulseLabelsClearOfTrails(CollisionsDemo demo, String where) {
        List<String> problems = new ArrayList<>();
        List<ScreenRect> labels = demo.copyImpulseLabelRects(new ArrayList<>());
        PlaneView plane = demo.getWindow().getPlaneView();
        Vector3f point = new Vector3f();
        for (ScreenRect label : labels) {
            for (DemoParticle other : demo.getParticles()) {
                if (demo.getWindow().getView(other).getNode().getCullHint()
                        == Spatial.CullHint.Always) {
                    continue;
                }
                Trail trail = demo.getWindow().getView(other).getTrail();
                float half = trail.getDrawnHalfWidth() * plane.getPixelsPerMetre();
                for (int age = 0; age < trail.size(); ++age) {
                    trail.copyPoint(age, point);
                    float x = plane.screenX(point.x);
                    float y = plane.screenY(point.y);
                    if (x > label.getX() - half + PIXEL && x < label.getRight() + half - PIXEL
                            && y > label.getY() - half + PIXEL
                            && y < label.getTop() + half - PIXEL) {
                        problems.add(where + ": impulse label " + label + " covers the trail"
                                + " of '" + other.getLabel() + "' at (" + x + ", " + y + ")");
                        break;
                    }
                }
            }
        }
        return problems;
    }

    /** Test whether a rectangle is among the texts shown (the same place). */
    private static boolean isShown(ScreenRect rect, List<ScreenRect> texts) {
        for (ScreenRect text : texts) {
            if (text.getX() == rect.getX() && text.getY() == rect.getY()
                    && text.getWidth() == rect.getWidth()
                    && text.getHeight() == rect.getHeight()) {
                return true;
            }
        }
        return false;
    }

    /** Test whether a shown joined label names the particle among its names. */
    private static boolean namedByJoinedLabel(DemoState demo, DemoParticle particle) {
        for (DemoParticle other : demo.getParticles()) {
            ParticleView view = demo.getWindow().getView(other);
            if (view.isLabelJoined() && !view.getLabelRect().isEmpty()) {
                // Names hold " = " themselves ("linear drag  F = -b V"): a name is found in the
                // text, not split out of it.
                if (view.getLabel().getText().contains(particle.getLabel())) {
                    return true;
                }
            }
        }
        return false;
    }
}
