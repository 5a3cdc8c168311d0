package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.lecture.WindDemo;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.AudioNodeSoundPlayer;
import particlelab.view.CollisionSounds;
import particlelab.view.SilentSoundPlayer;
import particlelab.view.SoundCue;
import particlelab.view.SoundLog;
import particlelab.view.SoundPlayer;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * No audio device: in a running (headless) application without an audio renderer, as the
 * launcher starts the window when {@code AudioProbe} finds no device, sounds are recorded and
 * shown, never played, and nothing fails.
 */
class SoundHeadlessTest {

    private static final float H = 1f / 60f;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(new WindDemo()));

    @Test
    void noAudioRendererMeansTheSilentPlayerAndNothingFails() throws Exception {
        Object[] result = harness.call(() -> {
            ParticleLabApp app = harness.app();
            SoundPlayer player = SoundPlayer.forApplication(app);
            // A dropped ball that is destroyed at its first bounce: impact and destroy sounds.
            World world = new World();
            world.addRule(SurfaceRule.ground(new ImpulseResponse(0.5f), Detection.SWEPT));
            Body ball = world.addBody(new ParticleIntegrator(new Gravity()),
                    new Vector3f(0f, 1f, 0f), Vector3f.ZERO, 1f, 0.1f);
            world.addContactListener(new ContactListener() {
                @Override
                public void resolved(Contact contact, World w) {
                    w.destroy(ball);
                }
            });
            CollisionSounds sounds = new CollisionSounds(player);
            sounds.attach(world);
            for (int frame = 0; frame < 120; ++frame) {
                world.step(H);
                sounds.playFrame(world);
                world.getImpacts().clear();
            }
            sounds.detach(world);
            return new Object[] {app.getAudioRenderer(), player};
        });
        assertNull(result[0], "the headless test application has no audio renderer");
        SoundPlayer player = (SoundPlayer) result[1];
        assertInstanceOf(SilentSoundPlayer.class, player);
        assertFalse(player.isAudible());
        SoundLog log = player.getLog();
        assertEquals(2, log.getTotal(), "one impact, one destroy");
        assertSame(SoundCue.IMPACT, log.getCue(0));
        assertSame(SoundCue.DESTROY, log.getCue(1));
        assertEquals("sound: destroy vol 1.00 (no audio device)",
                log.appendLatest(new StringBuilder()).toString());
    }

    @Test
    void theAppsAssetManagerFindsTheSoundsButOnlyAnAudioRendererCanPlayThem() throws Exception {
        Object[] result = harness.call(() -> {
            AudioNodeSoundPlayer player =
                    new AudioNodeSoundPlayer(harness.app().getAssetManager());
            float seconds = player.getNode(SoundCue.DESTROY).getAudioData().getDuration();
            IllegalStateException refused = assertThrows(IllegalStateException.class,
                    () -> player.play(SoundCue.IMPACT, 0.5f));
            return new Object[] {seconds, refused.getMessage()};
        });
        // assets/ is on the runtime classpath: jME loaded Sounds/destroy.wav.
        assertEquals((float) SoundCue.DESTROY.getDurationSeconds(), (float) result[0], 1e-4f);
        // Why SoundPlayer.forApplication never picks jME's player without a renderer.
        assertTrue(((String) result[1]).startsWith("No audio renderer"), (String) result[1]);
    }
}
