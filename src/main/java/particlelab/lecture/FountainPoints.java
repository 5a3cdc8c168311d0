package particlelab.lecture;

import java.util.Arrays;
import particlelab.view.PointCloudMesh;
import particlelab.world.Fountain;

/**
 * The fountain's pool written into a mesh of points once a frame, touching only what it must:
 * the positions of the particles in flight, three bulk copies of the fountain's planar array
 * into the mesh's planar buffers ({@link PointCloudMesh#writePositions}), and the colours that
 * changed. Slots that went back to the pool since the last frame are written too, black
 * (additive blending: invisible) at the nozzle; the slots beyond are dormant in the mesh
 * already, as in the pool, so they are not written again. The buffers then hold what a copy
 * of every slot would give, byte for byte (a test compares the two).
 *
 * <p>Colours: water at a fixed brightness (one packed colour for all of it: the fountain
 * gives all water {@link Fountain#WATER_COLOUR}), a shell at full brightness, a star or a
 * spark fading with what is left of its fuse, a dormant slot black. Water's and a dormant
 * slot's colour depend on the kind alone, so such a point's colour is written again only if
 * its slot's kind is not the one its colour was last written for: the kinds are compared in
 * bulk with {@link Arrays#mismatch(byte[], int, int, byte[], int, int)} (vectorised by the
 * JDK), which jumps from one changed slot to the next. The fireworks fade every frame: their
 * colours are written for the fountain's first slots, which hold them
 * ({@link Fountain#countFireworks}), a few thousand at most, without looking at the water.
 * Allocates nothing.
 */
public final class FountainPoints {

    /** The fireworks packed at a time before a bulk copy. */
    private static final int FIREWORK_CHUNK = 1024;
    /** A dormant slot's colour: black, opaque. */
    private static final int DORMANT_COLOUR = PointCloudMesh.pack(0, 0f);
    /** No kind: the colour of a point not written yet. */
    private static final byte UNWRITTEN = -1;

    private final PointCloudMesh mesh;
    /** The water's colour, packed once. */
    private final int waterPacked;
    /**
     * The kind each point's colour was last written for ({@link #UNWRITTEN}: none yet); for a
     * firework, its kind (its colour is written every update).
     */
    private final byte[] drawnKinds;
    /** Scratch: one chunk of the fireworks' packed colours. */
    private final int[] fireworkColours;
    /** How many points the last update wrote: beyond, the mesh holds dormant slots. */
    private int written;
    /** How many points the last update wrote, for a benchmark's plain copy. */
    private int lastWritten;

    /**
     * Write into a mesh with one point per slot of the pool.
     *
     * @param mesh the mesh (not null; its count is the pool size)
     * @param waterBrightness how bright water is drawn (0 to 1)
     */
    public FountainPoints(PointCloudMesh mesh, float waterBrightness) {
        if (!(waterBrightness >= 0f && waterBrightness <= 1f)) {
            throw new IllegalArgumentException("water brightness must be from 0 to 1, but was "
                    + waterBrightness);
        }
        this.mesh = mesh;
        waterPacked = PointCloudMesh.pack(Fountain.WATER_COLOUR, waterBrightness);
        drawnKinds = new byte[mesh.getCount()];
        Arrays.fill(drawnKinds, UNWRITTEN);
        fireworkColours = new int[Math.min(mesh.getCount(), FIREWORK_CHUNK)];
        written = mesh.getCount(); // the first update writes every point
    }

    /**
     * Copy the fountain's particles into the mesh and mark it updated.
     *
     * @param fountain the fountain (not null, its pool the mesh's count, not modified)
     */
    public void update(Fountain fountain) {
        int capacity = fountain.getCapacity();
        if (capacity != mesh.getCount()) {
            throw new IllegalArgumentException("the fountain's pool of " + capacity
                    + " does not match the mesh's " + mesh.getCount() + " points");
        }
        int live = fountain.countLive();
        // slots live to written − 1 went back to the pool since the last update: dormant now
        int points = Math.max(live, written);
        mesh.writePositions(0, fountain.getPositions(), capacity, points);
        writeChangedKinds(fountain.getKinds(), points);
        writeFireworks(fountain);
        mesh.markUpdated();
        written = live;
        lastWritten = points;
    }

    /**
     * Count the points whose positions the last {@link #update} wrote.
     *
     * @return the count (from 0 to the pool size)
     */
    public int countLastWritten() {
        return lastWritten;
    }

    /**
     * Slots 0 to points − 1 whose kind is not the one their colour was written for: water
     * and dormant slots get their colour, fireworks only their new kind here.
     */
    private void writeChangedKinds(byte[] kinds, int points) {
        byte[] drawn = drawnKinds;
        int i = 0;
        while (i < points) {
            int offset = Arrays.mismatch(kinds, i, points, drawn, i, points);
            if (offset < 0) {
                return; // the rest is as it was drawn
            }
            i += offset;
            byte kind = kinds[i];
            if (kind == Fountain.WATER) {
                mesh.writeColour(i, waterPacked);
            } else if (kind == Fountain.DORMANT) {
                mesh.writeColour(i, DORMANT_COLOUR);
            }
            drawn[i] = kind;
            ++i;
        }
    }

    /**
     * Every firework in flight: a shell at full brightness, the others fading; packed a
     * chunk at a time into a scratch and copied in bulk (the fireworks hold the first
     * slots).
     */
    private void writeFireworks(Fountain fountain) {
        int fireworks = fountain.countFireworks();
        int[] packed = fireworkColours;
        for (int start = 0; start < fireworks; start += packed.length) {
            int length = Math.min(packed.length, fireworks - start);
            for (int k = 0; k < length; ++k) {
                int i = start + k;
                float brightness = fountain.getKind(i) == Fountain.SHELL ? 1f
                        : fountain.fuseFraction(i);
                packed[k] = PointCloudMesh.pack(fountain.getColour(i), brightness);
            }
            mesh.writeColours(start, packed, length);
        }
    }
}
