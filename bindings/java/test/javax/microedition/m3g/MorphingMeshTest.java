package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static javax.microedition.m3g.GeometryFixtures.strip;
import static javax.microedition.m3g.GeometryFixtures.vertexBuffer;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 MorphingMesh: targets, weights, copies, identity and the specified exceptions. */
public class MorphingMeshTest {
    private static final float EPS = 0.0f;

    private static MorphingMesh twoTargets() {
        return new MorphingMesh(vertexBuffer(4), new VertexBuffer[] {vertexBuffer(4), vertexBuffer(4)}, strip(),
                null);
    }

    @Test
    public void targetsAndDefaults() {
        VertexBuffer base = vertexBuffer(4);
        VertexBuffer[] targets = {vertexBuffer(4), vertexBuffer(4), vertexBuffer(4)};
        TriangleStripArray ib = strip();
        Appearance a = new Appearance();
        MorphingMesh m = new MorphingMesh(base, targets, ib, a);
        assertEquals(3, m.getMorphTargetCount());
        for (int i = 0; i < 3; ++i) {
            assertSame(targets[i], m.getMorphTarget(i));
        }
        assertSame(base, m.getVertexBuffer());
        assertSame(ib, m.getIndexBuffer(0));
        assertSame(a, m.getAppearance(0));
        float[] weights = {5, 5, 5};
        m.getWeights(weights);
        assertArrayEquals(new float[3], weights, EPS);
        // The targets array was copied.
        VertexBuffer first = targets[0];
        targets[0] = vertexBuffer(4);
        assertSame(first, m.getMorphTarget(0));
    }

    @Test
    public void submeshArrays() {
        IndexBuffer[] submeshes = {strip(), strip()};
        Appearance[] appearances = {new Appearance(), new Appearance()};
        MorphingMesh m = new MorphingMesh(vertexBuffer(4), new VertexBuffer[] {vertexBuffer(4)}, submeshes,
                appearances);
        assertEquals(2, m.getSubmeshCount());
        assertEquals(1, m.getMorphTargetCount());
        assertSame(submeshes[1], m.getIndexBuffer(1));
        assertSame(appearances[1], m.getAppearance(1));
    }

    @Test
    public void weights() {
        MorphingMesh m = twoTargets();
        float[] in = {-0.5f, 1.75f, 42f};  // any value; past the count ignored
        m.setWeights(in);
        in[0] = 9;
        float[] out = {7, 7, 7};
        m.getWeights(out);
        assertArrayEquals(new float[] {-0.5f, 1.75f, 7}, out, EPS);
    }

    @Test
    public void weightArrayExceptions() {
        MorphingMesh m = twoTargets();
        assertThrowsExactly(NullPointerException.class, () -> m.setWeights(null));
        assertThrowsExactly(NullPointerException.class, () -> m.getWeights(null));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setWeights(new float[1]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setWeights(new float[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getWeights(new float[1]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getWeights(new float[0]));
    }

    @Test
    public void targetIndex() {
        MorphingMesh m = twoTargets();
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getMorphTarget(-1));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getMorphTarget(2));
    }

    @Test
    public void constructorExceptions() {
        VertexBuffer vb = vertexBuffer(4);
        VertexBuffer[] targets = {vertexBuffer(4)};
        assertThrowsExactly(NullPointerException.class, () -> new MorphingMesh(vb, null, strip(), null));
        assertThrowsExactly(NullPointerException.class,
                () -> new MorphingMesh(vb, new VertexBuffer[] {vertexBuffer(4), null}, strip(), null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new MorphingMesh(vb, new VertexBuffer[0], strip(), null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new MorphingMesh(vb, new VertexBuffer[0], new IndexBuffer[] {strip()}, null));
        assertThrowsExactly(NullPointerException.class,
                () -> new MorphingMesh(vb, (VertexBuffer[]) null, new IndexBuffer[] {strip()}, null));
        // The Mesh checks.
        assertThrowsExactly(NullPointerException.class, () -> new MorphingMesh(null, targets, strip(), null));
        assertThrowsExactly(NullPointerException.class,
                () -> new MorphingMesh(vb, targets, (IndexBuffer) null, null));
        assertThrowsExactly(NullPointerException.class,
                () -> new MorphingMesh(vb, targets, (IndexBuffer[]) null, null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new MorphingMesh(vb, targets, new IndexBuffer[0], null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new MorphingMesh(vb, targets, new IndexBuffer[] {strip(), strip()}, new Appearance[1]));
    }

    @Test
    public void duplicateCopiesTheWeights() {
        MorphingMesh m = twoTargets();
        m.setWeights(new float[] {0.25f, 0.5f});
        Object3D copy = m.duplicate();
        assertTrue(copy instanceof MorphingMesh);
        MorphingMesh c = (MorphingMesh) copy;
        assertSame(m.getMorphTarget(1), c.getMorphTarget(1));
        float[] out = new float[2];
        c.getWeights(out);
        assertArrayEquals(new float[] {0.25f, 0.5f}, out, EPS);
        m.setWeights(new float[] {1, 1});
        c.getWeights(out);
        assertArrayEquals(new float[] {0.25f, 0.5f}, out, EPS);
    }
}
