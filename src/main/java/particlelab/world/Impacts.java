package particlelab.world;

import com.jme3.math.Vector3f;

/**
 * The prologue's effects queue: one event per accepted contact whose normal approach speed
 * exceeds the hit threshold, with a loudness that follows the approach speed, for a flash at
 * the contact point or a sound. A demo reads the events after {@code clock.advance} and then
 * calls {@link #clear()}. Bounded and preallocated: when full, the oldest event is dropped.
 */
public final class Impacts {

    /** One impact: a copy, valid until the queue is cleared or wraps. */
    public static final class Impact {
        private final Vector3f point = new Vector3f();
        private double timeSeconds;
        private int body;
        private float approachSpeed;
        private float loudness;

        private Impact() {
        }

        /** @return the world time of the impact (in seconds) */
        public double getTimeSeconds() {
            return timeSeconds;
        }

        /** @return the live copy of the contact point (in metres) */
        public Vector3f getPoint() {
            return point;
        }

        /** @return the id of the body that hit (body A) */
        public int getBody() {
            return body;
        }

        /** @return the normal approach speed (in m/s, above the hit threshold) */
        public float getApproachSpeed() {
            return approachSpeed;
        }

        /**
         * @return the loudness (0 to 1): {@code (v − v_hit)/(v_full − v_hit)}, clamped, v the
         *     approach speed
         */
        public float getLoudness() {
            return loudness;
        }
    }

    /** The default number of events kept. */
    public static final int DEFAULT_CAPACITY = 64;
    /** The default hit threshold (in m/s): slower contacts make no event. */
    public static final float DEFAULT_HIT_SPEED = 0.5f;
    /** The default approach speed at full loudness (in m/s). */
    public static final float DEFAULT_FULL_SPEED = 10f;

    private final Impact[] events;
    private int first;
    private int size;
    private long dropped;
    private float hitSpeed = DEFAULT_HIT_SPEED;
    private float fullSpeed = DEFAULT_FULL_SPEED;

    /**
     * Create a queue.
     *
     * @param capacity the most events kept (&ge;1)
     */
    public Impacts(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException(
                    "impact queue capacity must be >= 1, but was " + capacity);
        }
        events = new Impact[capacity];
        for (int i = 0; i < capacity; ++i) {
            events[i] = new Impact();
        }
    }

    /**
     * Alter the speeds that make an event and full loudness.
     *
     * @param newHitSpeed the hit threshold (in m/s, finite, &ge;0)
     * @param newFullSpeed the speed at full loudness (in m/s, finite, &gt; the hit threshold)
     */
    public void setSpeeds(float newHitSpeed, float newFullSpeed) {
        if (!(newHitSpeed >= 0f) || !Float.isFinite(newFullSpeed)
                || !(newFullSpeed > newHitSpeed)) {
            throw new IllegalArgumentException("hit speed must be finite and >= 0 and full"
                    + " speed finite and above it, but were " + newHitSpeed + " and "
                    + newFullSpeed + " m/s");
        }
        hitSpeed = newHitSpeed;
        fullSpeed = newFullSpeed;
    }

    /** @return the hit threshold (in m/s) */
    public float getHitSpeed() {
        return hitSpeed;
    }

    /** @return the count of events (0 to capacity) */
    public int size() {
        return size;
    }

    /**
     * Access an event, oldest first.
     *
     * @param index which one (&ge;0, &lt;{@link #size()})
     * @return the live event (not null)
     */
    public Impact get(int index) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException(
                    "impact index must be from 0 to " + (size - 1) + ", but was " + index);
        }
        return events[(first + index) % events.length];
    }

    /** @return the count of events dropped because the queue was full */
    public long getDropped() {
        return dropped;
    }

    /**
     * Forget every event (after handling them).
     */
    public void clear() {
        first = 0;
        size = 0;
    }

    /** Queue an event for a contact if it is fast enough. */
    void offer(Contact contact) {
        float speed = contact.approachSpeed;
        if (!(speed > hitSpeed)) {
            return;
        }
        Impact event;
        if (size < events.length) {
            event = events[(first + size) % events.length];
            ++size;
        } else {
            event = events[first];
            first = (first + 1) % events.length;
            ++dropped;
        }
        event.timeSeconds = contact.timeSeconds;
        event.point.set(contact.point);
        event.body = contact.bodyA.getId();
        event.approachSpeed = speed;
        event.loudness = Math.min(1f, (speed - hitSpeed) / (fullSpeed - hitSpeed));
    }
}
