package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.DesktopAssetManager;
import com.jme3.bounding.BoundingBox;
import com.jme3.material.RenderState;
import com.jme3.material.TechniqueDef;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.shader.Shader;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The point cloud's planar mesh (x, y, z in three vertex buffers of one float a point) and the
 * material that draws it: the buffers the shader reads are the ones the mesh fills, the
 * vertex count and the bound are right, and the render state is the one Unshaded was given
 * before (additive, no depth write, transparent bucket). No window: the material is loaded
 * by a desktop asset manager, not compiled (the pictures are compared in the report).
 */
class PointCloudViewTest {

    private static final int POINTS = 5;
    private static final float HALF_EXTENT = 40f;
    /** The vertex buffers holding x, y and z, in order, and the shader's name for each. */
    private static final VertexBuffer.Type[] AXES = {VertexBuffer.Type.Position,
        VertexBuffer.Type.TexCoord, VertexBuffer.Type.TexCoord2};

    /**
     * The colour levels' rounding is Math.round at every float from 0 to 255 (about 1.1e9 of
     * them: an exhaustive check, a second or two), so the fast form changes no byte.
     */
    @Test
    void levelsRoundAsMathRoundAtEveryFloatFromZeroTo255() {
        int last = Float.floatToRawIntBits(255f);
        int wrong = 0;
        float firstWrong = Float.NaN;
        for (int bits = 0; bits <= last; ++bits) {
            float level = Float.intBitsToFloat(bits);
            if (PointCloudMesh.roundLevel(level) != Math.round(level)) {
                if (wrong++ == 0) {
                    firstWrong = level;
                }
            }
        }
        assertEquals(0, wrong, "levels rounded otherwise, the first " + firstWrong);
    }

    @Test
    void theMeshHasOneFloatAPointOnEachAxisAndItsOwnBound() {
        PointCloudMesh points = new PointCloudMesh(POINTS, HALF_EXTENT);
        Mesh mesh = points.getMesh();
        // jME takes the vertex count from Position: one float a point, so POINTS vertices
        assertEquals(POINTS, mesh.getVertexCount());
        for (int axis = 0; axis < AXES.length; ++axis) {
            VertexBuffer buffer = mesh.getBuffer(AXES[axis]);
            assertNotNull(buffer, AXES[axis] + " buffer");
            assertEquals(1, buffer.getNumComponents(), AXES[axis] + " components");
            assertEquals(VertexBuffer.Format.Float, buffer.getFormat());
            assertSame(points.getPositionData(axis), buffer.getData(), "axis " + axis);
        }
        VertexBuffer colour = mesh.getBuffer(VertexBuffer.Type.Color);
        assertEquals(4, colour.getNumComponents());
        assertEquals(VertexBuffer.Format.UnsignedByte, colour.getFormat());
        assertTrue(colour.isNormalized(), "colour bytes read as 0 to 1");
        BoundingBox bound = (BoundingBox) mesh.getBound();
        assertEquals(Vector3f.ZERO, bound.getCenter());
        assertEquals(HALF_EXTENT, bound.getXExtent(), 0f);
        assertEquals(HALF_EXTENT, bound.getYExtent(), 0f);
        assertEquals(HALF_EXTENT, bound.getZExtent(), 0f);
    }

    @Test
    void positionsAreCopiedAxisByAxisFromThePlanarArray() {
        PointCloudMesh points = new PointCloudMesh(POINTS, HALF_EXTENT);
        int stride = 7; // a pool larger than the points written
        float[] planar = new float[3 * stride];
        for (int k = 0; k < planar.length; ++k) {
            planar[k] = k + 0.5f;
        }
        points.writePositions(1, planar, stride, 3);
        for (int axis = 0; axis < AXES.length; ++axis) {
            // points 0 and 4 not written: still at the origin; 1 to 3 from the axis's block
            assertEquals(0f, points.getPositionData(axis).get(0), 0f);
            assertEquals(0f, points.getPositionData(axis).get(4), 0f);
            for (int i = 1; i <= 3; ++i) {
                // a copy, no arithmetic: exact
                assertEquals(axis * stride + i + 0.5f, points.getPositionData(axis).get(i), 0f);
            }
        }
        // Three from point 3 of five: the two the mesh has are written, not the third
        // (issue 36: nothing past a buffer's end, and nothing thrown on the render thread).
        points.writePositions(3, planar, stride, 3);
        for (int axis = 0; axis < AXES.length; ++axis) {
            assertEquals(axis * stride + 4 + 0.5f, points.getPositionData(axis).get(4), 0f);
        }
        // A planar array that cannot hold the points is the caller's mistake: refused.
        IllegalArgumentException tooShort = assertThrows(IllegalArgumentException.class,
                () -> points.writePositions(0, planar, 2, 3));
        assertTrue(tooShort.getMessage().contains("stride of 2"), tooShort.getMessage());
    }

    @Test
    void theMaterialReadsTheMeshsBuffersAndBlendsAsBefore() throws IOException {
        DesktopAssetManager assets = new DesktopAssetManager(true);
        PointCloudView view = new PointCloudView(assets, "cloud", POINTS, 2f, HALF_EXTENT);
        Geometry geometry = view.getGeometry();
        assertSame(view.getPoints().getMesh(), geometry.getMesh());
        assertEquals(RenderQueue.Bucket.Transparent, geometry.getQueueBucket());
        RenderState state = geometry.getMaterial().getAdditionalRenderState();
        assertEquals(RenderState.BlendMode.Additive, state.getBlendMode());
        assertFalse(state.isDepthWrite(), "depth write");
        assertEquals(2f, (Float) geometry.getMaterial().getParam("PointSize").getValue(), 0f);

        List<TechniqueDef> techniques = geometry.getMaterial().getMaterialDef()
                .getTechniqueDefs(TechniqueDef.DEFAULT_TECHNIQUE_NAME);
        Set<String> languages = new HashSet<>();
        for (TechniqueDef technique : techniques) {
            languages.add(technique.getShaderProgramLanguage(Shader.ShaderType.Vertex));
        }
        assertEquals(Set.of("GLSL100", "GLSL150"), languages);
        String vertex = resource(techniques.get(0)
                .getShaderProgramName(Shader.ShaderType.Vertex));
        // jME binds a buffer of type T to the attribute inT: one float each, x, y, z in order
        for (VertexBuffer.Type axis : AXES) {
            assertTrue(vertex.contains("attribute float in" + axis.name() + ";"),
                    "the vertex shader reads " + axis + " as one float");
        }
        assertTrue(vertex.contains("vec4(inPosition, inTexCoord, inTexCoord2, 1.0)"),
                "x, y, z in order");
        assertTrue(vertex.contains("attribute vec4 inColor;"), "vertex colour");
        assertTrue(vertex.contains("gl_PointSize = m_PointSize;"), "point size");
    }

    private static String resource(String path) throws IOException {
        try (InputStream in = PointCloudViewTest.class.getClassLoader()
                .getResourceAsStream(path)) {
            assertNotNull(in, path);
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
