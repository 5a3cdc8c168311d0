package particlelab.world;

import com.jme3.math.Vector3f;

/**
 * A bounded log of every contact a {@link World} found, oldest first: when full, each new
 * entry overwrites the oldest. Entries are preallocated, so logging allocates nothing; they
 * hold body numbers, not bodies, so a destroyed body leaves nothing behind here.
 */
public final class ContactLog {

    /** One logged contact: a copy, safe to read after the step. */
    public static final class Entry {
        private final Vector3f normal = new Vector3f();
        private long sequence;
        private double timeSeconds;
        private int bodyA;
        private int bodyB;
        private CollisionRule rule;
        private boolean swept;
        private float approachSpeed;
        private float penetration;
        private float impulse;
        private Contact.Prologue prologue;
        private Contact.Resolution resolution;
        private String epilogueNote;

        private Entry() {
        }

        /** @return the contact's sequence number in its world (&ge;0) */
        public long getSequence() {
            return sequence;
        }

        /** @return the world time of the contact (in seconds) */
        public double getTimeSeconds() {
            return timeSeconds;
        }

        /** @return body A's id */
        public int getBodyA() {
            return bodyA;
        }

        /** @return body B's id, or -1 for a static surface */
        public int getBodyB() {
            return bodyB;
        }

        /** @return the rule that found the contact (not null) */
        public CollisionRule getRule() {
            return rule;
        }

        /** @return true if the swept test found it, false for the overlap test */
        public boolean isSwept() {
            return swept;
        }

        /** @return the live copy of the unit normal, from B towards A */
        public Vector3f getNormal() {
            return normal;
        }

        /** @return the normal approach speed when found (in m/s, positive closing) */
        public float getApproachSpeed() {
            return approachSpeed;
        }

        /** @return the penetration when found (in metres) */
        public float getPenetration() {
            return penetration;
        }

        /** @return the impulse along the normal (in N·s) */
        public float getImpulse() {
            return impulse;
        }

        /** @return what the prologue decided (not null) */
        public Contact.Prologue getPrologue() {
            return prologue;
        }

        /** @return what the resolution did (not null) */
        public Contact.Resolution getResolution() {
            return resolution;
        }

        /** @return what the epilogue noted, or null */
        public String getEpilogueNote() {
            return epilogueNote;
        }

        @Override
        public String toString() {
            return "#" + sequence + " t=" + timeSeconds + " s, body " + bodyA + " vs "
                    + (bodyB < 0 ? "surface" : "body " + bodyB) + ", approach "
                    + approachSpeed + " m/s, " + prologue + ", " + resolution + ", j = "
                    + impulse + " N s" + (epilogueNote == null ? "" : ", " + epilogueNote);
        }
    }

    /** The default number of entries kept. */
    public static final int DEFAULT_CAPACITY = 256;

    private final Entry[] entries;
    private int first;
    private int size;
    private long total;

    /**
     * Create a log.
     *
     * @param capacity the most entries kept (&ge;1)
     */
    public ContactLog(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException(
                    "log capacity must be >= 1, but was " + capacity);
        }
        entries = new Entry[capacity];
        for (int i = 0; i < capacity; ++i) {
            entries[i] = new Entry();
        }
    }

    /**
     * Count the entries kept.
     *
     * @return the count (0 to {@link #capacity()})
     */
    public int size() {
        return size;
    }

    /**
     * Return the most entries kept.
     *
     * @return the capacity (&ge;1)
     */
    public int capacity() {
        return entries.length;
    }

    /**
     * Count every contact logged since the last clear, including those overwritten.
     *
     * @return the count (&ge;0)
     */
    public long getTotal() {
        return total;
    }

    /**
     * Access an entry, oldest first.
     *
     * @param index which one (&ge;0, &lt;{@link #size()})
     * @return the live entry (not null; overwritten when the log wraps)
     */
    public Entry get(int index) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException(
                    "log index must be from 0 to " + (size - 1) + ", but was " + index);
        }
        return entries[(first + index) % entries.length];
    }

    /**
     * Access the newest entry.
     *
     * @return the live entry, or null if the log is empty
     */
    public Entry latest() {
        return size == 0 ? null : get(size - 1);
    }

    /**
     * Forget every entry.
     */
    public void clear() {
        for (int i = 0; i < entries.length; ++i) {
            entries[i].rule = null;
            entries[i].epilogueNote = null;
        }
        first = 0;
        size = 0;
        total = 0L;
    }

    void record(Contact contact) {
        Entry entry;
        if (size < entries.length) {
            entry = entries[(first + size) % entries.length];
            ++size;
        } else {
            entry = entries[first];
            first = (first + 1) % entries.length;
        }
        ++total;
        entry.sequence = contact.sequence;
        entry.timeSeconds = contact.timeSeconds;
        entry.bodyA = contact.bodyA.getId();
        entry.bodyB = contact.bodyB == null ? -1 : contact.bodyB.getId();
        entry.rule = contact.rule;
        entry.swept = contact.swept;
        entry.normal.set(contact.normal);
        entry.approachSpeed = contact.approachSpeed;
        entry.penetration = contact.penetrationMetres;
        entry.impulse = contact.impulse;
        entry.prologue = contact.prologue;
        entry.resolution = contact.resolution;
        entry.epilogueNote = contact.epilogueNote;
    }
}
