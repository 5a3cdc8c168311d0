package particlelab.demo;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.List;
import particlelab.world.StateRing;

/**
 * A fingerprint of the state a demo shows, to tell two runs apart bit for bit: the 64-bit
 * FNV-1a hash of the ints of its replay ring's entry for that step (the demo's simulation:
 * t, every particle's P and V, the world, the demo's declared records, floats as their raw
 * bits; see {@link DemoRun}), without the ints of what the views show (the exact ghosts,
 * the kept shots: {@link DemoRun#countViewStateInts}), which a run without a window has
 * fewer of. Before the first step the ring holds nothing: the hash is then
 * that of t and every particle's P and V, in the ring's order. Two states with the same hash
 * are, short of a 1 in 2^64 collision, the same bits; a state that differs in one bit of one
 * float hashes differently.
 */
public final class StateHash {

    /** FNV-1a's 64-bit offset basis and prime. */
    private static final long OFFSET_BASIS = 0xcbf29ce484222325L;
    private static final long PRIME = 0x100000001b3L;
    private static final int BYTE_BITS = 8;
    private static final int BYTES_PER_INT = 4;
    private static final int BYTE_MASK = 0xff;

    private StateHash() {
    }

    /**
     * Hash the state a demo shows (the live end, or the recorded step shown).
     *
     * @param demo the demo (not null)
     * @return the hash
     */
    public static long of(DemoState demo) {
        StateRing ring = demo.getRun().getStateRing();
        long shown = demo.getRun().getShownStep();
        if (ring.size() > 0 && shown >= ring.getFirstIndex() && shown <= ring.getLastIndex()) {
            int[] entry = ring.copyEntry(shown);
            int simulation = Math.max(0, entry.length - demo.getRun().countViewStateInts());
            return of(Arrays.copyOf(entry, simulation));
        }
        long hash = OFFSET_BASIS;
        long time = Double.doubleToRawLongBits(demo.getWorld().getTimeSeconds());
        hash = mix(hash, (int) (time >>> Integer.SIZE));
        hash = mix(hash, (int) time);
        List<DemoParticle> particles = demo.getParticles();
        for (int i = 0; i < particles.size(); ++i) {
            hash = mix(hash, particles.get(i).getParticle().position);
            hash = mix(hash, particles.get(i).getParticle().velocity);
        }
        return hash;
    }

    /**
     * Hash a recorded state's ints.
     *
     * @param ints the ints (not null)
     * @return the hash
     */
    public static long of(int[] ints) {
        long hash = OFFSET_BASIS;
        for (int i = 0; i < ints.length; ++i) {
            hash = mix(hash, ints[i]);
        }
        return hash;
    }

    /**
     * Write a hash as 16 lower-case hex digits.
     *
     * @param hash the hash
     * @return the text (not null)
     */
    public static String hex(long hash) {
        String digits = Long.toHexString(hash);
        return "0".repeat(16 - digits.length()) + digits;
    }

    private static long mix(long hash, Vector3f vector) {
        long result = mix(hash, Float.floatToRawIntBits(vector.x));
        result = mix(result, Float.floatToRawIntBits(vector.y));
        return mix(result, Float.floatToRawIntBits(vector.z));
    }

    /** Feed an int's four bytes, lowest first, to FNV-1a. */
    private static long mix(long hash, int value) {
        long result = hash;
        for (int b = 0; b < BYTES_PER_INT; ++b) {
            result ^= (value >>> (b * BYTE_BITS)) & BYTE_MASK;
            result *= PRIME;
        }
        return result;
    }
}
