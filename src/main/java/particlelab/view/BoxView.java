package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;

/**
 * A lit box drawn by moving its mesh's vertices with a matrix R itself: each vertex at body
 * coordinates b is written to {@code P + R·b}. A jME spatial keeps its rotation as a
 * quaternion, which is always a rotation and would hide the drift of the plain matrix Euler
 * step; this view shows R as it is, so a matrix that has grown or sheared draws a box that has
 * grown or sheared.
 *
 * <p>Between two physics steps it may draw the blend of the two states
 * ({@link #update(Matrix3f, Vector3f, Matrix3f, Vector3f, float)}): the centre by
 * {@code P_prev + α·(P − P_prev)}, R by an {@link OrientationBlend}, so slow motion is smooth.
 *
 * <p>The mesh's buffers are allocated once; {@link #update} writes them in place and
 * allocates nothing. The front face (body +z) and the back face (body −z) have colours of
 * their own, so a box that turns over shows it.
 */
public final class BoxView {

    private static final int FACES = 6;
    private static final int VERTICES = 4 * FACES;
    private static final int FLOATS = 3 * VERTICES;
    /** Each face: its normal axis (0, 1, 2) and sign, in the order +x, −x, +y, −y, +z, −z. */
    private static final int[] FACE_AXIS = {0, 0, 1, 1, 2, 2};
    private static final float[] FACE_SIGN = {1f, -1f, 1f, -1f, 1f, -1f};
    /** How much the back face's colour is darkened, and the sides' (fractions). */
    private static final float BACK_SHADE = 0.45f;
    private static final float SIDE_SHADE = 0.75f;

    /** The vertices and normals in body coordinates (in metres; unit normals). */
    private final float[] bodyPositions = new float[FLOATS];
    private final float[] bodyNormals = new float[FLOATS];
    private final FloatBuffer positions = BufferUtils.createFloatBuffer(FLOATS);
    private final FloatBuffer normals = BufferUtils.createFloatBuffer(FLOATS);
    private final VertexBuffer positionBuffer;
    private final VertexBuffer normalBuffer;
    private final Geometry geometry;
    /** Scratch: the blended orientation and centre between two steps. */
    private final OrientationBlend orientationBlend = new OrientationBlend();
    private final Matrix3f drawnOrientation = new Matrix3f();
    private final Vector3f drawnCentre = new Vector3f();

    /**
     * Create a box view, at the origin with the identity orientation.
     *
     * @param assetManager loads the material (not null)
     * @param name the geometry's name (not null)
     * @param halfExtents half the box's sides along the body x, y, z axes (in metres, each
     *     finite and &gt;0, not null, not modified)
     * @param color the front face's colour; the others are shades of it (not null, not
     *     modified)
     */
    public BoxView(AssetManager assetManager, String name, Vector3f halfExtents,
            ColorRGBA color) {
        if (!(halfExtents.x > 0f && halfExtents.y > 0f && halfExtents.z > 0f)
                || !Float.isFinite(halfExtents.x + halfExtents.y + halfExtents.z)) {
            throw new IllegalArgumentException(
                    "box half extents (m) must be finite and > 0, but were " + halfExtents);
        }
        FloatBuffer colors = BufferUtils.createFloatBuffer(4 * VERTICES);
        ShortBuffer indices = BufferUtils.createShortBuffer(6 * FACES);
        float[] half = {halfExtents.x, halfExtents.y, halfExtents.z};
        for (int face = 0; face < FACES; ++face) {
            int axis = FACE_AXIS[face];
            float sign = FACE_SIGN[face];
            // The face's two in-plane axes, ordered so the corners run counter-clockwise
            // seen from outside.
            int u = (axis + 1) % 3;
            int v = (axis + 2) % 3;
            float[] cornerU = {-1f, 1f, 1f, -1f};
            float[] cornerV = sign > 0f ? new float[] {-1f, -1f, 1f, 1f}
                    : new float[] {1f, 1f, -1f, -1f};
            float shade = axis != 2 ? SIDE_SHADE : sign > 0f ? 1f : BACK_SHADE;
            for (int corner = 0; corner < 4; ++corner) {
                int base = 3 * (4 * face + corner);
                bodyPositions[base + axis] = sign * half[axis];
                bodyPositions[base + u] = cornerU[corner] * half[u];
                bodyPositions[base + v] = cornerV[corner] * half[v];
                bodyNormals[base + axis] = sign;
                colors.put(shade * color.r).put(shade * color.g).put(shade * color.b)
                        .put(color.a);
            }
            short first = (short) (4 * face);
            indices.put(first).put((short) (first + 1)).put((short) (first + 2));
            indices.put(first).put((short) (first + 2)).put((short) (first + 3));
        }
        colors.flip();
        indices.flip();
        Mesh mesh = new Mesh();
        mesh.setBuffer(VertexBuffer.Type.Position, 3, positions);
        mesh.setBuffer(VertexBuffer.Type.Normal, 3, normals);
        mesh.setBuffer(VertexBuffer.Type.Color, 4, colors);
        mesh.setBuffer(VertexBuffer.Type.Index, 3, indices);
        mesh.setStreamed();
        positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        normalBuffer = mesh.getBuffer(VertexBuffer.Type.Normal);
        Material lit = new Material(assetManager, "Common/MatDefs/Light/Lighting.j3md");
        lit.setBoolean("UseMaterialColors", true);
        lit.setBoolean("UseVertexColor", true);
        lit.setColor("Diffuse", ColorRGBA.White.clone());
        lit.setColor("Ambient", new ColorRGBA(0.6f, 0.6f, 0.6f, 1f));
        lit.setColor("Specular", new ColorRGBA(0.3f, 0.3f, 0.3f, 1f));
        lit.setFloat("Shininess", 16f);
        geometry = new Geometry(name, mesh);
        geometry.setMaterial(lit);
        // The vertices move every frame: never culled, so no bounds are recomputed.
        geometry.setCullHint(Spatial.CullHint.Never);
        update(new Matrix3f(), Vector3f.ZERO);
    }

    /**
     * Access the geometry to attach to a scene.
     *
     * @return the live geometry (not null)
     */
    public Geometry getGeometry() {
        return geometry;
    }

    /**
     * Move every vertex to {@code P + R·b} and turn every normal by R (normalised, for the
     * lighting only). Allocates nothing.
     *
     * @param r R, any matrix: a rotation, or one that has drifted (not null, not modified)
     * @param centre P (in metres, not null, not modified)
     */
    public void update(Matrix3f r, Vector3f centre) {
        float r00 = r.get(0, 0);
        float r01 = r.get(0, 1);
        float r02 = r.get(0, 2);
        float r10 = r.get(1, 0);
        float r11 = r.get(1, 1);
        float r12 = r.get(1, 2);
        float r20 = r.get(2, 0);
        float r21 = r.get(2, 1);
        float r22 = r.get(2, 2);
        for (int i = 0; i < FLOATS; i += 3) {
            float x = bodyPositions[i];
            float y = bodyPositions[i + 1];
            float z = bodyPositions[i + 2];
            positions.put(i, centre.x + r00 * x + r01 * y + r02 * z);
            positions.put(i + 1, centre.y + r10 * x + r11 * y + r12 * z);
            positions.put(i + 2, centre.z + r20 * x + r21 * y + r22 * z);
            x = bodyNormals[i];
            y = bodyNormals[i + 1];
            z = bodyNormals[i + 2];
            float nx = r00 * x + r01 * y + r02 * z;
            float ny = r10 * x + r11 * y + r12 * z;
            float nz = r20 * x + r21 * y + r22 * z;
            float length = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
            float scale = length > 0f ? 1f / length : 0f;
            normals.put(i, nx * scale).put(i + 1, ny * scale).put(i + 2, nz * scale);
        }
        positions.rewind();
        normals.rewind();
        positionBuffer.updateData(positions);
        normalBuffer.updateData(normals);
    }

    /**
     * Draw the box between two physics states, at {@code α = leftover / h}: the centre at
     * {@code P_prev + α·(P − P_prev)}, the orientation by {@link OrientationBlend} (α = 1:
     * the state after the step, exactly as {@link #update(Matrix3f, Vector3f)}). Allocates
     * nothing.
     *
     * @param previousR R before the last step (not null, not modified)
     * @param previousCentre P before the last step (in metres, not null, not modified)
     * @param r R after it (not null, not modified)
     * @param centre P after it (in metres, not null, not modified)
     * @param alpha the blend (0 to 1; clamped)
     */
    public void update(Matrix3f previousR, Vector3f previousCentre, Matrix3f r,
            Vector3f centre, float alpha) {
        if (alpha >= 1f) {
            update(r, centre);
            return;
        }
        float a = Math.max(0f, alpha);
        drawnCentre.set(previousCentre).interpolateLocal(centre, a);
        update(orientationBlend.blend(previousR, r, a, drawnOrientation), drawnCentre);
    }

    /**
     * Copy where one vertex of the mesh is now, as last written by {@link #update}.
     *
     * @param vertex the vertex (0 to 23)
     * @param storeResult storage for the position (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyVertex(int vertex, Vector3f storeResult) {
        if (vertex < 0 || vertex >= VERTICES) {
            throw new IllegalArgumentException(
                    "vertex must be from 0 to " + (VERTICES - 1) + ", but was " + vertex);
        }
        int base = 3 * vertex;
        return storeResult.set(positions.get(base), positions.get(base + 1),
                positions.get(base + 2));
    }

    /**
     * Copy one vertex in body coordinates.
     *
     * @param vertex the vertex (0 to 23)
     * @param storeResult storage for the position (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyBodyVertex(int vertex, Vector3f storeResult) {
        if (vertex < 0 || vertex >= VERTICES) {
            throw new IllegalArgumentException(
                    "vertex must be from 0 to " + (VERTICES - 1) + ", but was " + vertex);
        }
        int base = 3 * vertex;
        return storeResult.set(bodyPositions[base], bodyPositions[base + 1],
                bodyPositions[base + 2]);
    }
}
