package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.scene.Spatial;
import com.jme3.scene.Node;
import java.util.List;
import particlelab.view.ShotTrail;
import particlelab.view.Trail;

/**
 * The last few launches, kept on screen: when a demo launches again (a reset, a fire), each
 * particle's trail is copied into a faint path and the parameter values it flew with are
 * remembered. Older shots fade; each is described by what differed from the launch now, e.g.
 * "h = 1/10 s vs 1/60 s". A key clears them. Keeping a shot allocates nothing.
 *
 * <p>How many shots were kept is part of the demo's recorded state: after a step back to
 * before a launch ({@link #showUpTo}), the shots kept since are neither drawn nor listed; a
 * step forward shows them again, and a launch from there replaces them (that future is gone).
 */
final class KeptShots {

    /** How many launches are kept. */
    static final int SHOTS = 5;
    /** How many particles of a launch are kept (the first ones; a fountain keeps 4). */
    static final int MAX_PARTICLES = 4;
    /** The opacity of each kept shot, newest first. */
    private static final float[] OPACITY = {0.55f, 0.42f, 0.32f, 0.24f, 0.17f};
    /** The kept paths' width (as a fraction of the particles' drawn radius). */
    private static final float WIDTH_FRACTION = 0.25f;

    private ShotTrail[][] paths = new ShotTrail[0][0];
    private final float[][] values = new float[SHOTS][];
    private final float[] now;
    /** The values the shot in the air was launched with. */
    private final float[] launched;
    private List<DemoParticle> particles;
    /** The scene whose particle views' trails are kept. */
    private DemoScene scene;
    /** Ring index of the newest shot (-1: none). */
    private int newest = -1;
    private int count;
    private int kept;
    /** How many shots the state shown had kept: the later ones are hidden. */
    private int shown;

    /**
     * Create the store.
     *
     * @param parameterCount how many parameters the demo declares (&ge;0)
     */
    KeptShots(int parameterCount) {
        for (int i = 0; i < SHOTS; ++i) {
            values[i] = new float[parameterCount];
        }
        now = new float[parameterCount];
        launched = new float[parameterCount];
    }

    /**
     * Remember the values a shot is launched with: at the start, and after each launch's
     * waiting values were applied. Allocates nothing.
     *
     * @param parameters the demo's parameters (not null)
     */
    void launched(DemoParameters parameters) {
        parameters.copyValuesInScene(launched);
    }

    /**
     * Build the paths, hidden, for the first particles of a demo. Call once, after the
     * scene's views were built.
     *
     * @param assets loads the material (not null)
     * @param demoParticles the demo's particles (not null, live)
     * @param demoScene the scene holding their views, built (not null)
     * @param radiusMetres the particles' drawn radius (in metres, &gt;0)
     * @param sceneNode where to attach the paths (not null, modified)
     */
    void build(AssetManager assets, List<DemoParticle> demoParticles, DemoScene demoScene,
            float radiusMetres, Node sceneNode) {
        particles = demoParticles;
        scene = demoScene;
        int perShot = Math.min(MAX_PARTICLES, demoParticles.size());
        Material unshaded = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        paths = new ShotTrail[SHOTS][perShot];
        for (int shot = 0; shot < SHOTS; ++shot) {
            for (int p = 0; p < perShot; ++p) {
                Trail trail = demoScene.viewOf(demoParticles.get(p)).getTrail();
                ShotTrail path = new ShotTrail("kept shot " + shot + " of "
                        + demoParticles.get(p).getLabel(), trail.getCapacity(),
                        WIDTH_FRACTION * radiusMetres, unshaded);
                paths[shot][p] = path;
                sceneNode.attachChild(path.getGeometry());
            }
        }
    }

    /**
     * Keep the shot that is ending: copy the trails and the values it was launched with.
     * Does nothing before {@link #build}, or when no trail has moved. Allocates nothing.
     */
    void keep() {
        if (particles == null || paths[0].length == 0 || !anyMoved()) {
            return;
        }
        dropHidden();
        newest = (newest + 1) % SHOTS;
        for (int p = 0; p < paths[newest].length; ++p) {
            paths[newest][p].copyFrom(scene.viewOf(particles.get(p)).getTrail());
        }
        System.arraycopy(launched, 0, values[newest], 0, launched.length);
        count = Math.min(count + 1, SHOTS);
        ++kept;
        shown = kept;
        fade();
    }

    /** Forget every kept shot. */
    void clear() {
        for (int shot = 0; shot < paths.length; ++shot) {
            for (int p = 0; p < paths[shot].length; ++p) {
                paths[shot][p].clear();
            }
        }
        count = 0;
        newest = -1;
    }

    /**
     * Show the shots as a recorded state had them: those kept after it are hidden (a step
     * back to before their launch), or shown again (a step forward). Allocates nothing.
     *
     * @param keptThen {@link #countKept()} in that state (&ge;0)
     */
    void showUpTo(int keptThen) {
        int newShown = Math.max(0, Math.min(kept, keptThen));
        if (newShown != shown) {
            shown = newShown;
            fade();
        }
    }

    /** @return how many shots are on screen (from 0 to {@link #SHOTS}) */
    int size() {
        return Math.max(0, count - hiddenCount());
    }

    /** @return how many shots were kept since the demo started, cleared or not */
    int countKept() {
        return kept;
    }

    /** @return how many shots are held to be drawn now (&ge;0, at most {@link #SHOTS}) */
    int countHeld() {
        return count;
    }

    /**
     * Count the kept paths drawn: holding points and not hidden.
     *
     * @return the count (&ge;0)
     */
    int countDrawnPaths() {
        int drawn = 0;
        for (int shot = 0; shot < paths.length; ++shot) {
            for (int p = 0; p < paths[shot].length; ++p) {
                ShotTrail path = paths[shot][p];
                if (path.size() > 0
                        && path.getGeometry().getCullHint() != Spatial.CullHint.Always) {
                    ++drawn;
                }
            }
        }
        return drawn;
    }

    /**
     * Access one kept path.
     *
     * @param age 0 for the newest shot (&lt;{@link #size()})
     * @param particle which of the first particles (&lt;{@link #MAX_PARTICLES})
     * @return the live path (not null)
     */
    ShotTrail getPath(int age, int particle) {
        return paths[ringIndex(age + hiddenCount())][particle];
    }

    /**
     * Write the legend: one line per kept shot, newest first, saying what its launch's
     * values were against the values in the scene now. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param parameters the demo's parameters (not null)
     * @return text
     */
    StringBuilder formatLegend(StringBuilder text, DemoParameters parameters) {
        int visible = size();
        if (visible == 0) {
            return text;
        }
        parameters.copyValuesInScene(now);
        text.append("Kept shots (faint, newest brightest):");
        for (int age = 0; age < visible; ++age) {
            text.append('\n').append(age + 1).append(".  ");
            int slot = ringIndex(age + hiddenCount());
            if (parameters.appendDifferences(text, values[slot], now) == 0) {
                text.append("same values as now");
            }
        }
        return text;
    }

    private boolean anyMoved() {
        for (int p = 0; p < paths[0].length; ++p) {
            if (scene.viewOf(particles.get(p)).getTrail().size() >= 2) {
                return true;
            }
        }
        return false;
    }

    /** The shots kept after the state shown: the newest ones, hidden. */
    private int hiddenCount() {
        return Math.min(count, kept - shown);
    }

    /** Forget the hidden shots: a launch from the state shown replaces them. */
    private void dropHidden() {
        int hidden = hiddenCount();
        for (int age = 0; age < hidden; ++age) {
            ShotTrail[] shot = paths[ringIndex(age)];
            for (int p = 0; p < shot.length; ++p) {
                shot[p].clear();
                shot[p].getGeometry().setCullHint(Spatial.CullHint.Inherit);
            }
        }
        newest = (newest - hidden + SHOTS) % SHOTS;
        count -= hidden;
        kept = shown;
        if (count == 0) {
            newest = -1;
        }
    }

    /** Fade the shown shots by age, and hide those kept after the state shown. */
    private void fade() {
        int hidden = hiddenCount();
        for (int age = 0; age < count; ++age) {
            ShotTrail[] shot = paths[ringIndex(age)];
            for (int p = 0; p < shot.length; ++p) {
                if (age < hidden) {
                    shot[p].getGeometry().setCullHint(Spatial.CullHint.Always);
                } else {
                    shot[p].getGeometry().setCullHint(Spatial.CullHint.Inherit);
                    shot[p].setOpacity(particles.get(p).getColor(), OPACITY[age - hidden]);
                }
            }
        }
    }

    private int ringIndex(int age) {
        return (newest - age + SHOTS) % SHOTS;
    }
}
