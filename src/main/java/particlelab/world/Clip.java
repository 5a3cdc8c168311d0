package particlelab.world;

import com.jme3.math.Vector3f;

/**
 * An authored collision response as data, the way an artist's animation is: for each body it
 * moves (a <em>track</em>, named "rocket", "target"), keyframes of its offset from where it was
 * at the contact, at times from the contact, played with linear interpolation between keys; a
 * track holds its last key once it is over. The clip is the same whatever the impact: it
 * knows neither the speed, the angle nor the masses. Made by {@link ClipReader} from a small
 * text file; played by a demo that sets its kinematic bodies' velocities from it.
 *
 * <p>Every track starts at {@code t = 0} with offset 0 (the body starts where the contact left
 * it) and has at least two keys, their times increasing. Immutable; allocates nothing.
 */
public final class Clip {

    private final String name;
    private final String[] trackNames;
    /** Per track: the key times (in seconds from the contact, increasing, the first 0). */
    private final float[][] times;
    /** Per track: the key offsets, x, y, z per key (in metres from the body at the contact). */
    private final float[][] offsets;

    /**
     * Create a clip from checked keys ({@link ClipReader} checks them).
     *
     * @param name the clip's name, e.g. its file name (not null)
     * @param trackNames the tracks' names (not null, copied)
     * @param times per track, the key times (not null, copied)
     * @param offsets per track, 3 offsets per key (not null, copied)
     */
    Clip(String name, String[] trackNames, float[][] times, float[][] offsets) {
        this.name = name;
        this.trackNames = trackNames.clone();
        this.times = new float[times.length][];
        this.offsets = new float[offsets.length][];
        for (int i = 0; i < times.length; ++i) {
            this.times[i] = times[i].clone();
            this.offsets[i] = offsets[i].clone();
        }
    }

    /**
     * Return the clip's name.
     *
     * @return the name it was read as, e.g. {@code "topple.clip"} (not null)
     */
    public String getName() {
        return name;
    }

    /**
     * Count the tracks.
     *
     * @return the count (&ge;1)
     */
    public int countTracks() {
        return trackNames.length;
    }

    /**
     * Return a track's name.
     *
     * @param track the track's index (0 to {@link #countTracks()}−1)
     * @return its name, e.g. "rocket" (not null)
     */
    public String getTrackName(int track) {
        return trackNames[track];
    }

    /**
     * Find a track by its name.
     *
     * @param trackName the name (case-sensitive)
     * @return its index, or -1 if the clip has no such track
     */
    public int indexOf(String trackName) {
        for (int i = 0; i < trackNames.length; ++i) {
            if (trackNames[i].equals(trackName)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Count a track's keys.
     *
     * @param track the track's index
     * @return the count (&ge;2)
     */
    public int countKeys(int track) {
        return times[track].length;
    }

    /**
     * Return the time of a track's key.
     *
     * @param track the track's index
     * @param key the key's index (0 to {@link #countKeys}−1)
     * @return its time (in seconds from the contact, &ge;0)
     */
    public float getKeySeconds(int track, int key) {
        return times[track][key];
    }

    /**
     * Return how long the clip plays: its latest key.
     *
     * @return the duration (in seconds, &gt;0)
     */
    public float getDurationSeconds() {
        float duration = 0f;
        for (int i = 0; i < times.length; ++i) {
            duration = Math.max(duration, times[i][times[i].length - 1]);
        }
        return duration;
    }

    /**
     * Copy a track's offset at a time of the clip into storeResult: linear between the keys
     * around it, {@code o = o_k + (t − t_k)/(t_k+1 − t_k)·(o_k+1 − o_k)}; 0 before the clip,
     * the last key after it.
     *
     * @param track the track's index
     * @param clipSeconds the time since the contact (in seconds)
     * @param storeResult storage for the offset (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyOffset(int track, double clipSeconds, Vector3f storeResult) {
        float[] t = times[track];
        float[] o = offsets[track];
        int last = t.length - 1;
        if (!(clipSeconds > 0.0)) {
            return storeResult.set(o[0], o[1], o[2]);
        }
        if (clipSeconds >= t[last]) {
            return storeResult.set(o[3 * last], o[3 * last + 1], o[3 * last + 2]);
        }
        int k = 0;
        while (t[k + 1] <= clipSeconds) {
            ++k;
        }
        float u = (float) ((clipSeconds - t[k]) / (t[k + 1] - t[k]));
        int at = 3 * k;
        return storeResult.set(o[at] + u * (o[at + 3] - o[at]),
                o[at + 1] + u * (o[at + 4] - o[at + 1]),
                o[at + 2] + u * (o[at + 5] - o[at + 2]));
    }

    /**
     * Copy the velocity a track starts with into storeResult: the slope of its first segment,
     * {@code (o_1 − o_0)/(t_1 − t_0)}, what the clip says the body leaves the impact with.
     *
     * @param track the track's index
     * @param storeResult storage for the velocity (in m/s, not null, modified)
     * @return storeResult
     */
    public Vector3f copyStartVelocity(int track, Vector3f storeResult) {
        float[] o = offsets[track];
        float span = times[track][1] - times[track][0];
        return storeResult.set((o[3] - o[0]) / span, (o[4] - o[1]) / span,
                (o[5] - o[2]) / span);
    }
}
