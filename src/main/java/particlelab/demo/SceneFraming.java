package particlelab.demo;

import java.util.List;
import particlelab.physics.SimulationClock;

/**
 * The camera's frame of a demo's scene, beside its base class: the declared region, widened
 * to what the launches reach ({@link LaunchReach}: each grounded particle in flight flown
 * ahead with its own integrator and h), or narrowed to a top the demo chose
 * ({@link DemoWindow#setViewTop}); the scene's texts laid out again and the application's
 * camera reframed whenever the frame changed. Only a launch, a reset or a new top reframes,
 * never a frame of its own.
 */
final class SceneFraming {

    private final DemoState demo;
    private final DemoScene scene;
    private final List<DemoParticle> particles;
    private final SimulationClock clock;
    /** What the launches reach, for the camera to frame. */
    private final LaunchReach reach = new LaunchReach();

    /**
     * Create the framing of a demo's scene.
     *
     * @param demo the demo, for its HUD, its state and its application's camera (not null)
     * @param scene the scene to frame (not null)
     * @param particles the demo's particles (not null, live)
     * @param clock the demo's clock, whose h the launches are flown with (not null)
     */
    SceneFraming(DemoState demo, DemoScene scene, List<DemoParticle> particles,
            SimulationClock clock) {
        this.demo = demo;
        this.scene = scene;
        this.particles = particles;
        this.clock = clock;
    }

    /** Frame the scene's region with the application's camera. */
    void frameCamera() {
        scene.frame(demo.getApplication().getCamera());
    }

    /**
     * Frame less than the whole region: up to a height, at most the region's top; the
     * camera is reframed at once if the window is there.
     *
     * @param topMetres the top edge to frame (in metres, finite, &gt;0)
     */
    void setTop(float topMetres) {
        scene.setFrameTop(topMetres);
        if (demo.getWindow().getHud() != null) {
            scene.layOut(demo.getWindow().getHud().getLayout());
            if (demo.isEnabled()) {
                frameCamera();
            }
        }
    }

    /**
     * Frame the region the launches reach, beyond the declared one if they go further: each
     * particle that stops at the ground and is in flight is flown ahead with its own
     * integrator and h, so the frame follows the launch speed, angle, g and coefficients the
     * particle has now. At every launch and reset.
     */
    void frameLaunches() {
        reach.clear();
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.stopsAtGround() && !particle.isHeld() && !particle.isParked()) {
                reach.include(particle, clock.getStepSeconds());
            }
        }
        if (scene.frameReach(reach) && demo.getWindow().getHud() != null) {
            scene.layOut(demo.getWindow().getHud().getLayout());
            scene.updateViews();
            if (demo.isEnabled()) {
                frameCamera();
            }
        }
    }
}
