package particlelab.lecture;

import java.util.Arrays;
import particlelab.view.PointCloudMesh;
import particlelab.world.Fountain;

/**
 * The fountain's pool written into a mesh of points once a frame, touching only what it must:
 * the positions of the particles in flight, interleaved a chunk at a time and copied in bulk
 * ({@link PointCloudMesh#writePositions}), and the colours that changed. Slots that went back
 * to the pool since the last frame are written too, black (additive blending: invisible) at
 * the nozzle; the slots beyond are dormant in the mesh already, as in the pool, so they are
 * not written again. The buffers then hold what a copy of every slot would give, byte for
 * byte (a test compares the two).
 *
 * <p>Colours: water at a fixed brightness (one packed colour for all of it: the fountain
 * gives all water {@link Fountain#WATER_COLOUR}), a shell at full brightness, a star or a
 * spark fading with what is left of its fuse, a dormant slot black. A point's colour is
 * written again only if it is a firework (it fades every frame) or its slot's kind is not the
 * one its colour was last written for: a water particle that moves into a slot that held
 * water keeps the colour there. Allocates nothing.
 */
public final class FountainPoints {

    /** A dormant slot's colour: black, opaque. */
    private static final int DORMANT_COLOUR = PointCloudMesh.pack(0, 0f);
    /** No kind: the colour of a point not written yet. */
    private static final byte UNWRITTEN = -1;

    private final PointCloudMesh mesh;
    /** The water's colour, packed once. */
    private final int waterPacked;
    /** The positions of one chunk of points, x, y, z per point (m). */
    private final float[] xyz;
    /** The kind each point's colour was last written for ({@link #UNWRITTEN}: none yet). */
    private final byte[] drawnKinds;
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
        xyz = new float[3 * Math.min(mesh.getCount(), PointCloudMesh.CHUNK_POINTS)];
        drawnKinds = new byte[mesh.getCount()];
        Arrays.fill(drawnKinds, UNWRITTEN);
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
        int points = Math.max(live, written);
        writePositions(fountain.getPositions(), capacity, points);
        byte[] drawn = drawnKinds;
        for (int i = 0; i < live; ++i) {
            byte kind = fountain.getKind(i);
            // nearly every point is water whose slot held water: nothing to write
            if (kind != Fountain.WATER || drawn[i] != Fountain.WATER) {
                mesh.writeColour(i, colour(fountain, i, kind));
                drawn[i] = kind;
            }
        }
        for (int i = live; i < points; ++i) {
            if (drawn[i] != Fountain.DORMANT) {
                mesh.writeColour(i, DORMANT_COLOUR);
                drawn[i] = Fountain.DORMANT;
            }
        }
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

    /** Points 0 to points − 1, a chunk at a time, interleaved in a scratch array. */
    private void writePositions(float[] planar, int capacity, int points) {
        float[] out = xyz;
        for (int start = 0; start < points; start += PointCloudMesh.CHUNK_POINTS) {
            int length = Math.min(PointCloudMesh.CHUNK_POINTS, points - start);
            int y = capacity + start;
            int z = 2 * capacity + start;
            for (int k = 0, at = 0; k < length; ++k, at += 3) {
                out[at] = planar[start + k];
                out[at + 1] = planar[y + k];
                out[at + 2] = planar[z + k];
            }
            mesh.writePositions(start, out, length);
        }
    }

    private int colour(Fountain fountain, int i, byte kind) {
        switch (kind) {
            case Fountain.WATER:
                return waterPacked;
            case Fountain.SHELL:
                return PointCloudMesh.pack(fountain.getColour(i), 1f);
            case Fountain.DORMANT:
                return DORMANT_COLOUR;
            default:
                return PointCloudMesh.pack(fountain.getColour(i), fountain.fuseFraction(i));
        }
    }
}
