package particlelab.world;

import java.util.ArrayList;
import java.util.List;

/**
 * A pooled, index-based list of contacts: {@link #add()} hands out a cleared contact from the
 * pool and grows it only when a step finds more contacts than any step before, so a scene
 * with a fixed set of bodies allocates nothing per step.
 */
public final class Contacts {

    private final List<Contact> pool = new ArrayList<>();
    private int size;

    /**
     * Create an empty list.
     */
    public Contacts() {
    }

    /**
     * Count the contacts in the list.
     *
     * @return the count (&ge;0)
     */
    public int size() {
        return size;
    }

    /**
     * Access a contact.
     *
     * @param index which one (&ge;0, &lt;{@link #size()})
     * @return the live contact (not null)
     */
    public Contact get(int index) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException(
                    "contact index must be from 0 to " + (size - 1) + ", but was " + index);
        }
        return pool.get(index);
    }

    /**
     * Append a cleared contact.
     *
     * @return the live contact to fill in (not null)
     */
    public Contact add() {
        if (size == pool.size()) {
            pool.add(new Contact());
        }
        Contact contact = pool.get(size++);
        contact.clear();
        return contact;
    }

    /**
     * Take back the contact {@link #add()} handed out last (a rule that found no contact
     * after all).
     */
    public void removeLast() {
        if (size == 0) {
            throw new IllegalStateException("no contact to remove: the list is empty");
        }
        pool.get(--size).clear();
    }

    /**
     * Empty the list, dropping every reference the contacts held.
     */
    public void clear() {
        for (int i = 0; i < size; ++i) {
            pool.get(i).clear();
        }
        size = 0;
    }

    /**
     * Count the contacts allocated so far, in use or not.
     *
     * @return the pool size (&ge;{@link #size()})
     */
    public int capacity() {
        return pool.size();
    }
}
