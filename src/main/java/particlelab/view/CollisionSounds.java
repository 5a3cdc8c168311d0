package particlelab.view;

import particlelab.world.Body;
import particlelab.world.BodyListener;
import particlelab.world.Impacts;
import particlelab.world.World;

/**
 * Turns a {@link World}'s collision events into sounds: the lecture's "play a sound" in the
 * prologue (at the moment of impact) and in the epilogue (a destroyed object).
 * <ul>
 * <li><b>Impacts</b>: {@link #playImpacts} plays {@link SoundCue#IMPACT} for each event of
 * {@link World#getImpacts()}, at the event's loudness {@code (v − v_hit)/(v_full − v_hit)}
 * clamped to 0..1, {@code v} the normal approach speed (only contacts faster than the hit
 * threshold make events). Call it once per frame, after {@code clock.advance}, before the
 * demo clears the queue; at most {@link #MAX_IMPACTS_PER_FRAME} a frame are played (the
 * rest are counted), so a pile of fragments does not take every audio channel.</li>
 * <li><b>Destroyed bodies</b>: registered with {@link #attach}, it hears bodies leave the
 * world and plays {@link SoundCue#DESTROY} for each one destroyed during a step, that is in
 * an epilogue. Bodies removed outside a step (a reset, a scene being rebuilt) make no
 * sound.</li>
 * </ul>
 * Allocates nothing per frame or per event.
 */
public final class CollisionSounds implements BodyListener {

    /** The most impact sounds played in one frame. */
    public static final int MAX_IMPACTS_PER_FRAME = 4;
    /** The volume of the destroy sound (0 to 1). */
    public static final float DESTROY_VOLUME = 1f;

    private final SoundPlayer player;
    private long skippedImpacts;

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
    }

    /**
     * Play the impact sound for the queued impact events, oldest first, up to
     * {@link #MAX_IMPACTS_PER_FRAME}. Does not clear the queue (the demo does, after its
     * flashes have read it too).
     *
     * @param impacts the world's impact queue (not null)
     * @return how many sounds were played (0 to {@link #MAX_IMPACTS_PER_FRAME})
     */
    public int playImpacts(Impacts impacts) {
        int count = impacts.size();
        int played = Math.min(count, MAX_IMPACTS_PER_FRAME);
        for (int i = 0; i < played; ++i) {
            player.play(SoundCue.IMPACT, impacts.get(i).getLoudness());
        }
        skippedImpacts += count - played;
        return played;
    }

    /**
     * Return how many impact events were not played because a frame had more than
     * {@link #MAX_IMPACTS_PER_FRAME}.
     *
     * @return the count (&ge;0)
     */
    public long getSkippedImpacts() {
        return skippedImpacts;
    }

    /**
     * Play the destroy sound when a body destroyed during a step (in an epilogue) leaves.
     *
     * @param world the world (not null)
     * @param body the body leaving (not null)
     */
    @Override
    public void bodyRemoved(World world, Body body) {
        if (world.isStepping()) {
            player.play(SoundCue.DESTROY, DESTROY_VOLUME);
        }
    }
}
