package particlelab.view;

import particlelab.world.Body;
import particlelab.world.BodyListener;
import particlelab.world.Impacts;
import particlelab.world.World;

/**
 * Turns a {@link World}'s collision events into sounds: the lecture's "play a sound" in the
 * prologue (at the moment of impact) and in the epilogue (a destroyed object). Like the
 * world's other effects, the sounds are queued during the steps and played after them, once
 * a frame, by {@link #playFrame}: call it after {@code clock.advance}, before the demo
 * clears the impact queue.
 * <ul>
 * <li><b>Impacts</b>: {@link SoundCue#IMPACT} for each event of {@link World#getImpacts()},
 * at the event's loudness {@code (v − v_hit)/(v_full − v_hit)} clamped to 0..1, {@code v}
 * the normal approach speed (only contacts faster than the hit threshold make events).</li>
 * <li><b>Destroyed bodies</b>: registered with {@link #attach}, it hears bodies leave the
 * world and queues {@link SoundCue#DESTROY} for each one destroyed during a step, that is in
 * an epilogue. Bodies removed outside a step (a reset, a scene being rebuilt) make no
 * sound.</li>
 * </ul>
 * A frame plays at most {@link #MAX_SOUNDS_PER_FRAME} of each (the rest are counted), so a
 * pile of fragments does not take every audio channel. Allocates nothing.
 */
public final class CollisionSounds implements BodyListener {

    /** The most impact sounds, and the most destroy sounds, played in one frame. */
    public static final int MAX_SOUNDS_PER_FRAME = 4;
    /** The volume of the destroy sound (0 to 1). */
    public static final float DESTROY_VOLUME = 1f;

    private final SoundPlayer player;
    private int pendingDestroys;
    private long skipped;

    /**
     * Create a bridge to a player.
     *
     * @param player where the sounds go (not null)
     */
    public CollisionSounds(SoundPlayer player) {
        if (player == null) {
            throw new IllegalArgumentException("sound player must not be null");
        }
        this.player = player;
    }

    /**
     * Access the player.
     *
     * @return the live player (not null)
     */
    public SoundPlayer getPlayer() {
        return player;
    }

    /**
     * Start hearing a world's destroyed bodies.
     *
     * @param world the world (not null)
     */
    public void attach(World world) {
        world.addBodyListener(this);
    }

    /**
     * Stop hearing a world's destroyed bodies (the symmetric half of {@link #attach}).
     *
     * @param world the world (not null)
     */
    public void detach(World world) {
        world.removeBodyListener(this);
        pendingDestroys = 0;
    }

    /**
     * Play the frame's sounds: the impact sound for each queued impact event, oldest first,
     * then the destroy sound for each body destroyed in an epilogue since the last frame, up
     * to {@link #MAX_SOUNDS_PER_FRAME} of each. Does not clear the impact queue (the demo
     * does, after its flashes have read it too). Call on the jME thread.
     *
     * @param world the world whose steps this frame took (not null)
     * @return how many sounds were played (&ge;0)
     */
    public int playFrame(World world) {
        Impacts impacts = world.getImpacts();
        int count = impacts.size();
        int impactSounds = Math.min(count, MAX_SOUNDS_PER_FRAME);
        for (int i = 0; i < impactSounds; ++i) {
            player.play(SoundCue.IMPACT, impacts.get(i).getLoudness());
        }
        int destroySounds = Math.min(pendingDestroys, MAX_SOUNDS_PER_FRAME);
        for (int i = 0; i < destroySounds; ++i) {
            player.play(SoundCue.DESTROY, DESTROY_VOLUME);
        }
        skipped += count - impactSounds + pendingDestroys - destroySounds;
        pendingDestroys = 0;
        return impactSounds + destroySounds;
    }

    /**
     * Return how many sounds were not played because a frame had more than
     * {@link #MAX_SOUNDS_PER_FRAME} of one kind.
     *
     * @return the count (&ge;0)
     */
    public long getSkipped() {
        return skipped;
    }

    /**
     * Queue the destroy sound when a body destroyed during a step (in an epilogue) leaves.
     *
     * @param world the world (not null)
     * @param body the body leaving (not null)
     */
    @Override
    public void bodyRemoved(World world, Body body) {
        if (world.isStepping()) {
            ++pendingDestroys;
        }
    }
}
