package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static javax.microedition.m3g.GeometryFixtures.strip;
import static javax.microedition.m3g.GeometryFixtures.vertexBuffer;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/**
 * JSR-184 1.1 SkinnedMesh: skeleton, bones, at-rest transforms, bone
 * vertices and the specified exceptions.
 */
public class SkinnedMeshTest {
    private static final float EPS = 1e-6f;

    private static Group group() {
        return new Group();
    }

    private static void addChild(Group parent, Node child) {
        parent.addChild(child);
    }

    private static void setTranslation(Node node, float x, float y, float z) {
        node.setTranslation(x, y, z);
    }


    @Test
    public void nullSkeleton() {
        VertexBuffer vb = vertexBuffer(4);
        assertThrowsExactly(NullPointerException.class, () -> new SkinnedMesh(vb, strip(), null, null));
        assertThrowsExactly(NullPointerException.class,
                () -> new SkinnedMesh(vb, new IndexBuffer[] {strip()}, null, null));
    }

    @Test
    public void meshChecksComeFirst() {
        VertexBuffer vb = vertexBuffer(4);
        assertThrowsExactly(NullPointerException.class, () -> new SkinnedMesh(null, strip(), null, null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new SkinnedMesh(vb, new IndexBuffer[0], null, null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new SkinnedMesh(vb, new IndexBuffer[] {strip(), strip()}, new Appearance[1], null));
    }

    // ---- With skeletons ----

    @Test
    public void skeletonAndMeshParts() {
        Group skeleton = group();
        VertexBuffer vb = vertexBuffer(4);
        TriangleStripArray ib = strip();
        Appearance a = new Appearance();
        SkinnedMesh m = new SkinnedMesh(vb, ib, a, skeleton);
        assertSame(skeleton, m.getSkeleton());
        assertSame(vb, m.getVertexBuffer());
        assertSame(ib, m.getIndexBuffer(0));
        assertSame(a, m.getAppearance(0));

        IndexBuffer[] submeshes = {strip(), strip()};
        Group other = group();
        SkinnedMesh two = new SkinnedMesh(vb, submeshes, null, other);
        assertEquals(2, two.getSubmeshCount());
        assertSame(submeshes[1], two.getIndexBuffer(1));
        assertSame(other, two.getSkeleton());
    }

    @Test
    public void skeletonMustBeFree() {
        Group parent = group();
        Group skeleton = group();
        addChild(parent, skeleton);
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new SkinnedMesh(vertexBuffer(4), strip(), null, skeleton));
        // Already another mesh's skeleton.
        Group used = group();
        new SkinnedMesh(vertexBuffer(4), strip(), null, used);
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new SkinnedMesh(vertexBuffer(4), strip(), null, used));
        World world = new World();
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new SkinnedMesh(vertexBuffer(4), strip(), null, world));
    }

    @Test
    public void boneVerticesAndWeights() {
        Group skeleton = group();
        Group a = group();
        Group b = group();
        Group unused = group();
        addChild(skeleton, a);
        addChild(a, b);
        addChild(skeleton, unused);
        SkinnedMesh m = new SkinnedMesh(vertexBuffer(4), strip(), null, skeleton);
        m.addTransform(a, 1, 0, 4);
        m.addTransform(b, 3, 2, 2);

        assertEquals(4, m.getBoneVertices(a, null, null));
        int[] indices = {-1, -1, -1, -1, -1};
        float[] weights = {-1, -1, -1, -1, -1};
        assertEquals(4, m.getBoneVertices(a, indices, weights));
        assertArrayEquals(new int[] {0, 1, 2, 3, -1}, indices);  // the rest is left alone
        assertArrayEquals(new float[] {1, 1, 0.25f, 0.25f, -1}, weights, EPS);

        int[] bIndices = new int[2];
        assertEquals(2, m.getBoneVertices(b, bIndices, null));
        assertArrayEquals(new int[] {2, 3}, bIndices);
        float[] bWeights = new float[2];
        assertEquals(2, m.getBoneVertices(b, null, bWeights));
        assertArrayEquals(new float[] {0.75f, 0.75f}, bWeights, EPS);

        // In the skeleton but never added.
        assertEquals(0, m.getBoneVertices(unused, new int[0], new float[0]));
        assertEquals(0, m.getBoneVertices(skeleton, null, null));

        assertThrowsExactly(IllegalArgumentException.class, () -> m.getBoneVertices(a, new int[3], null));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getBoneVertices(a, null, new float[3]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getBoneVertices(a, new int[0], null));
        assertThrowsExactly(NullPointerException.class, () -> m.getBoneVertices(null, null, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getBoneVertices(group(), null, null));
    }

    @Test
    public void boneTransformIsTheAtRestMatrix() {
        Group skeleton = group();
        Group bone = group();
        addChild(skeleton, bone);
        setTranslation(bone, 1, 2, 3);
        SkinnedMesh m = new SkinnedMesh(vertexBuffer(4), strip(), null, skeleton);
        m.addTransform(bone, 1, 0, 4);
        setTranslation(bone, 5, 5, 5);  // captured at the first addTransform

        Transform t = new Transform();
        t.postScale(2, 2, 2);
        m.getBoneTransform(bone, t);
        float[] matrix = new float[16];
        t.get(matrix);
        // Mesh space -> bone space: the inverse of the bone's translation then.
        assertArrayEquals(new float[] {1, 0, 0, -1, 0, 1, 0, -2, 0, 0, 1, -3, 0, 0, 0, 1}, matrix, EPS);

        // A skeleton node never added leaves the transform as it was.
        Group other = group();
        addChild(skeleton, other);
        Transform untouched = new Transform();
        untouched.postTranslate(7, 8, 9);
        m.getBoneTransform(other, untouched);
        untouched.get(matrix);
        assertArrayEquals(new float[] {1, 0, 0, 7, 0, 1, 0, 8, 0, 0, 1, 9, 0, 0, 0, 1}, matrix, EPS);

        assertThrowsExactly(NullPointerException.class, () -> m.getBoneTransform(null, new Transform()));
        assertThrowsExactly(NullPointerException.class, () -> m.getBoneTransform(bone, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getBoneTransform(group(), new Transform()));
    }

    @Test
    public void addTransformExceptions() {
        Group skeleton = group();
        Group bone = group();
        addChild(skeleton, bone);
        SkinnedMesh m = new SkinnedMesh(vertexBuffer(4), strip(), null, skeleton);
        assertThrowsExactly(NullPointerException.class, () -> m.addTransform(null, 1, 0, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.addTransform(group(), 1, 0, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.addTransform(bone, 0, 0, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.addTransform(bone, -1, 0, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.addTransform(bone, 1, 0, 0));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.addTransform(bone, 1, -1, 1));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.addTransform(bone, 1, 65535, 1));
        m.addTransform(skeleton, 1, 65534, 1);  // the skeleton itself is a bone too
        assertEquals(1, m.getBoneVertices(skeleton, null, null));
    }

    @Test
    public void duplicateIsASkinnedMesh() {
        Group skeleton = group();
        SkinnedMesh m = new SkinnedMesh(vertexBuffer(4), strip(), null, skeleton);
        Object3D copy = m.duplicate();
        assertTrue(copy instanceof SkinnedMesh);
        SkinnedMesh c = (SkinnedMesh) copy;
        assertSame(m.getVertexBuffer(), c.getVertexBuffer());
        assertTrue(c.getSkeleton() != skeleton);  // the skeleton is part of the copied subtree
    }
}
