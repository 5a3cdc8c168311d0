package particlelab.world;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;

/**
 * A cursor over one preallocated block of {@code int}s, where a {@link StateRecord} writes its
 * state and reads it back, bit for bit: a float as its raw bits
 * ({@link Float#floatToRawIntBits}), a double or a long as two ints, a boolean as 0 or 1. The
 * {@link StateRing} points a slab at one of its entries before each write or read; nothing
 * here allocates.
 */
public final class StateSlab {

    /** Bits per int: the high half of a long is shifted by this. */
    private static final int INT_BITS = 32;
    /** The low 32 bits of a long. */
    private static final long LOW_BITS = 0xFFFF_FFFFL;

    private int[] data = new int[0];
    private int start;
    private int limit;
    private int at;

    /**
     * Point the slab at a block of an array and put the cursor at its start.
     *
     * @param newData the array (not null, written or read from now on)
     * @param newStart the block's first index (&ge;0)
     * @param newLimit one past the block's last index (&ge;newStart, &le;newData.length)
     */
    public void point(int[] newData, int newStart, int newLimit) {
        if (newData == null || newStart < 0 || newLimit < newStart
                || newLimit > newData.length) {
            throw new IllegalArgumentException("block must lie in the array, but was "
                    + newStart + " to " + newLimit + " of "
                    + (newData == null ? "null" : newData.length + " ints"));
        }
        data = newData;
        start = newStart;
        limit = newLimit;
        at = newStart;
    }

    /**
     * Count the ints written or read since the slab was pointed.
     *
     * @return the count (&ge;0)
     */
    public int position() {
        return at - start;
    }

    /**
     * Write an int.
     *
     * @param value the value
     */
    public void putInt(int value) {
        if (at == limit) {
            throw new IllegalStateException("a state record wrote more than the "
                    + (limit - start) + " ints it declared (countStateInts)");
        }
        data[at++] = value;
    }

    /**
     * Write a float, as its raw bits.
     *
     * @param value the value (any, NaN's payload kept)
     */
    public void putFloat(float value) {
        putInt(Float.floatToRawIntBits(value));
    }

    /**
     * Write a long, as two ints.
     *
     * @param value the value
     */
    public void putLong(long value) {
        putInt((int) (value >>> INT_BITS));
        putInt((int) value);
    }

    /**
     * Write a double, as its raw bits in two ints.
     *
     * @param value the value (any)
     */
    public void putDouble(double value) {
        putLong(Double.doubleToRawLongBits(value));
    }

    /**
     * Write a boolean, as 1 or 0.
     *
     * @param value the value
     */
    public void putBoolean(boolean value) {
        putInt(value ? 1 : 0);
    }

    /**
     * Write a vector's three components.
     *
     * @param value the vector (not null, not modified)
     */
    public void putVector(Vector3f value) {
        putFloat(value.x);
        putFloat(value.y);
        putFloat(value.z);
    }

    /**
     * Write a matrix's nine entries, row by row.
     *
     * @param value the matrix (not null, not modified)
     */
    public void putMatrix(Matrix3f value) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                putFloat(value.get(row, column));
            }
        }
    }

    /**
     * Write a run of floats, as their raw bits: one loop, for a packed batch.
     *
     * @param values the array (not null, not modified)
     * @param from the first index written
     * @param count how many (&ge;0)
     */
    public void putFloats(float[] values, int from, int count) {
        ensure(count, "wrote more than");
        for (int i = 0; i < count; ++i) {
            data[at + i] = Float.floatToRawIntBits(values[from + i]);
        }
        at += count;
    }

    /**
     * Write a run of ints: one copy, for a packed batch.
     *
     * @param values the array (not null, not modified)
     * @param from the first index written
     * @param count how many (&ge;0)
     */
    public void putInts(int[] values, int from, int count) {
        ensure(count, "wrote more than");
        System.arraycopy(values, from, data, at, count);
        at += count;
    }

    /**
     * Read a run of floats written by {@link #putFloats}.
     *
     * @param storeResult where to put them (not null, modified)
     * @param from the first index read into
     * @param count how many (&ge;0)
     */
    public void getFloats(float[] storeResult, int from, int count) {
        ensure(count, "read more than");
        for (int i = 0; i < count; ++i) {
            storeResult[from + i] = Float.intBitsToFloat(data[at + i]);
        }
        at += count;
    }

    /**
     * Read a run of ints written by {@link #putInts}.
     *
     * @param storeResult where to put them (not null, modified)
     * @param from the first index read into
     * @param count how many (&ge;0)
     */
    public void getInts(int[] storeResult, int from, int count) {
        ensure(count, "read more than");
        System.arraycopy(data, at, storeResult, from, count);
        at += count;
    }

    /**
     * Read an int.
     *
     * @return the value written there
     */
    public int getInt() {
        if (at == limit) {
            throw new IllegalStateException("a state record read more than the "
                    + (limit - start) + " ints recorded");
        }
        return data[at++];
    }

    /**
     * Read a float.
     *
     * @return the value written there, bit for bit
     */
    public float getFloat() {
        return Float.intBitsToFloat(getInt());
    }

    /**
     * Read a long.
     *
     * @return the value written there
     */
    public long getLong() {
        long high = getInt();
        long low = getInt() & LOW_BITS;
        return high << INT_BITS | low;
    }

    /**
     * Read a double.
     *
     * @return the value written there, bit for bit
     */
    public double getDouble() {
        return Double.longBitsToDouble(getLong());
    }

    /**
     * Read a boolean.
     *
     * @return the value written there
     */
    public boolean getBoolean() {
        return getInt() != 0;
    }

    /**
     * Read a vector's three components.
     *
     * @param storeResult storage for the vector (not null, modified)
     * @return storeResult
     */
    public Vector3f getVector(Vector3f storeResult) {
        float x = getFloat();
        float y = getFloat();
        float z = getFloat();
        return storeResult.set(x, y, z);
    }

    /**
     * Read a matrix's nine entries, row by row.
     *
     * @param storeResult storage for the matrix (not null, modified)
     * @return storeResult
     */
    public Matrix3f getMatrix(Matrix3f storeResult) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                storeResult.set(row, column, getFloat());
            }
        }
        return storeResult;
    }

    private void ensure(int count, String what) {
        if (count < 0 || count > limit - at) {
            throw new IllegalStateException("a state record " + what + " the "
                    + (limit - start) + " ints it has (countStateInts), by a run of " + count);
        }
    }
}
