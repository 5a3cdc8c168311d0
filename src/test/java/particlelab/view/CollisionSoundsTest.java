package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.Impacts;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

class CollisionSoundsTest {

    private static final float H = 1f / 60f;
    private static final float RADIUS = 0.1f;

    @Test
    void eachImpactPlaysAtItsLoudnessFromTheApproachSpeed() {
        World world = groundWorld(0.5f);
        world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, 2f, 0f),
                Vector3f.ZERO, 1f, RADIUS);
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        CollisionSounds sounds = new CollisionSounds(player);
        int impacts = 0;
        int events = 0;
        for (int frame = 0; frame < 300; ++frame) {
            world.step(H);
            Impacts queue = world.getImpacts();
            for (int i = 0; i < queue.size(); ++i) {
                Impacts.Impact impact = queue.get(i);
                float v = impact.getApproachSpeed();
                // Loudness (v − v_hit)/(v_full − v_hit), clamped to 0..1.
                float expected = Math.min(1f, (v - Impacts.DEFAULT_HIT_SPEED)
                        / (Impacts.DEFAULT_FULL_SPEED - Impacts.DEFAULT_HIT_SPEED));
                assertEquals(expected, impact.getLoudness(), 1e-6f);
            }
            int before = (int) player.getLog().getTotal();
            assertEquals(Math.min(queue.size(), CollisionSounds.MAX_SOUNDS_PER_FRAME),
                    sounds.playFrame(world));
            for (int i = 0; i < queue.size(); ++i) {
                int entry = player.getLog().size() - queue.size() + i;
                assertSame(SoundCue.IMPACT, player.getLog().getCue(entry));
                assertEquals(queue.get(i).getLoudness(), player.getLog().getVolume(entry), 0f);
            }
            impacts += (int) player.getLog().getTotal() - before;
            events += queue.size();
            queue.clear();
        }
        // The centre falls 1.9 m to the touch, e = 0.5: ideal approach speeds eⁿ·√(2g·1.9 m)
        // = 6.10, 3.05, 1.53, 0.76, 0.38 m/s, so three or four impacts (the step's own
        // errors decide the fourth, close to the 0.5 m/s hit threshold) made a sound each.
        assertEquals(events, impacts, "one impact sound per event");
        assertTrue(events >= 3 && events <= 4, "impact events: " + events);
        assertEquals(0L, sounds.getSkipped());
    }

    @Test
    void aCrowdedFramePlaysOnlyTheCapAndCountsTheRest() {
        World world = groundWorld(0.5f);
        int balls = CollisionSounds.MAX_SOUNDS_PER_FRAME + 3;
        for (int i = 0; i < balls; ++i) {
            world.addBody(new ParticleIntegrator(new Gravity()),
                    new Vector3f(i, 1f, 0f), Vector3f.ZERO, 1f, RADIUS);
        }
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        CollisionSounds sounds = new CollisionSounds(player);
        while (world.getImpacts().size() == 0) {
            world.step(H);
        }
        // Same height, same step: every ball hits the ground in the same step.
        assertEquals(balls, world.getImpacts().size());
        assertEquals(CollisionSounds.MAX_SOUNDS_PER_FRAME, sounds.playFrame(world));
        assertEquals(CollisionSounds.MAX_SOUNDS_PER_FRAME, player.getLog().getTotal());
        assertEquals(3L, sounds.getSkipped());
    }

    @Test
    void aBodyDestroyedInTheEpiloguePlaysTheDestroySoundAfterItsImpactButAResetDoesNot() {
        World world = groundWorld(0.5f);
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Body target = world.addBody(gravity, new Vector3f(0f, 1f, 0f), Vector3f.ZERO, 1f,
                RADIUS);
        Body bystander = world.addBody(gravity, new Vector3f(5f, 50f, 0f), Vector3f.ZERO, 1f,
                RADIUS);
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World w) {
                if (contact.getBodyA() == target) {
                    w.destroy(target);
                }
            }
        });
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        CollisionSounds sounds = new CollisionSounds(player);
        sounds.attach(world);
        while (world.countBodies() == 2) {
            world.step(H);
        }
        assertEquals(0, player.getLog().getTotal(), "nothing is played inside the steps");
        assertEquals(2, sounds.playFrame(world));
        // The lecture's order: the impact (prologue), then the destroyed target (epilogue).
        assertSame(SoundCue.IMPACT, player.getLog().getCue(0));
        assertSame(SoundCue.DESTROY, player.getLog().getCue(1));
        assertEquals(CollisionSounds.DESTROY_VOLUME, player.getLog().getVolume(1), 0f);
        world.getImpacts().clear();

        // Removed outside a step (a scene being rebuilt): no sound.
        world.destroy(bystander);
        world.restart();
        assertEquals(0, sounds.playFrame(world));
        assertEquals(2, player.getLog().getTotal());

        sounds.detach(world);
        assertEquals(0, world.countBodyListeners());
    }

    @Test
    void playingAFramesImpactsAllocatesNothing() {
        World world = groundWorld(0.5f);
        for (int i = 0; i < 3; ++i) {
            world.addBody(new ParticleIntegrator(new Gravity()),
                    new Vector3f(i, 1f, 0f), Vector3f.ZERO, 1f, RADIUS);
        }
        while (world.getImpacts().size() == 0) {
            world.step(H);
        }
        CollisionSounds sounds =
                new CollisionSounds(new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE));
        Allocations.assertAllocatesNothing("10_000 frames of impact sounds", () -> {
            for (int i = 0; i < 10_000; ++i) {
                sounds.playFrame(world);
            }
        });
    }

    private static World groundWorld(float restitution) {
        World world = new World();
        world.addRule(SurfaceRule.ground(new ImpulseResponse(restitution), Detection.SWEPT));
        return world;
    }
}
