package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.Random;
import particlelab.collision.ThinWall;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * The tunnelling experiment, shared by {@code particle-lab tunnel} and the report: shots of
 * radius r fired straight at a thin wall of thickness D, each from a random phase of one
 * step's travel, counting the shots whose contact the wall's rule resolved.
 *
 * <p>A shot starts at {@code x = −(r + D/2) − (1 + φ)·v·h}, with φ one
 * {@link Random#nextFloat()} per shot, and flies at +v along x with no force until the wall
 * resolves a contact or it is a step past the far face. The overlap test misses with the
 * probability {@link ThinWall#overlapMissProbability}; the swept test never misses.
 */
public final class TunnelShots {

    private TunnelShots() {
    }

    /** Notes whether the shot in flight hit. */
    private static final class HitFlag implements ContactListener {
        private boolean hit;

        @Override
        public void resolved(Contact contact, World world) {
            hit = true;
        }
    }

    /**
     * Fire the shots.
     *
     * @param wall the wall, its normal along +x (not null)
     * @param speed the shots' speed v (in m/s, &gt;0)
     * @param radius the shots' radius r (in m, &gt;0)
     * @param stepSeconds the step h (in s, &gt;0)
     * @param detection the wall's test (not null)
     * @param shots how many shots (&ge;0)
     * @param random the phases' source (not null, advanced once per shot)
     * @return the number of shots the wall's test saw
     */
    public static int fire(ThinWall wall, float speed, float radius, float stepSeconds,
            Detection detection, int shots, Random random) {
        Validate.notNull(wall, "wall");
        Validate.notNull(detection, "detection");
        Validate.notNull(random, "random");
        World world = new World(1);
        Vector3f start = new Vector3f();
        Vector3f velocity = new Vector3f(speed, 0f, 0f);
        Body shot = world.addBody(new ParticleIntegrator(), start, velocity, 1f, radius);
        world.addRule(new SurfaceRule("wall", wall, new ImpulseResponse(1f, 0f, false),
                detection));
        HitFlag flag = new HitFlag();
        world.addContactListener(flag);
        float reach = radius + 0.5f * wall.getThickness();
        float travel = speed * stepSeconds;
        float beyond = reach + travel;
        int hits = 0;
        for (int i = 0; i < shots; ++i) {
            start.set(-reach - (1f + random.nextFloat()) * travel, 0f, 0f);
            shot.setLaunch(start, velocity);
            world.restart();
            flag.hit = false;
            while (!flag.hit && shot.getPosition().x <= beyond) {
                world.step(stepSeconds);
            }
            if (flag.hit) {
                ++hits;
            }
        }
        return hits;
    }
}
