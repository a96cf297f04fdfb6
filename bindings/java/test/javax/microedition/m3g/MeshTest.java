package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static javax.microedition.m3g.GeometryFixtures.strip;
import static javax.microedition.m3g.GeometryFixtures.vertexBuffer;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 Mesh: both constructors, submesh accessors, identity, array copies and the specified exceptions. */
public class MeshTest {
    @Test
    public void oneSubmesh() {
        VertexBuffer vb = vertexBuffer(4);
        TriangleStripArray ib = strip();
        Appearance a = new Appearance();
        Mesh m = new Mesh(vb, ib, a);
        assertEquals(1, m.getSubmeshCount());
        assertSame(vb, m.getVertexBuffer());
        assertSame(ib, m.getIndexBuffer(0));
        assertSame(a, m.getAppearance(0));

        Mesh noAppearance = new Mesh(vb, ib, null);
        assertNull(noAppearance.getAppearance(0));
    }

    @Test
    public void submeshArrays() {
        VertexBuffer vb = vertexBuffer(4);
        IndexBuffer[] submeshes = {strip(), strip(), strip()};
        Appearance[] appearances = {new Appearance(), null, new Appearance(), new Appearance()};
        Mesh m = new Mesh(vb, submeshes, appearances);
        assertEquals(3, m.getSubmeshCount());
        for (int i = 0; i < 3; ++i) {
            assertSame(submeshes[i], m.getIndexBuffer(i));
            assertSame(appearances[i], m.getAppearance(i));
        }
        // The arrays were copied.
        IndexBuffer first = submeshes[0];
        Appearance firstAppearance = appearances[0];
        submeshes[0] = strip();
        appearances[0] = new Appearance();
        assertSame(first, m.getIndexBuffer(0));
        assertSame(firstAppearance, m.getAppearance(0));

        // Null appearances: none for every submesh.
        Mesh bare = new Mesh(vb, new IndexBuffer[] {strip(), strip()}, null);
        assertEquals(2, bare.getSubmeshCount());
        assertNull(bare.getAppearance(0));
        assertNull(bare.getAppearance(1));
    }

    @Test
    public void manySubmeshes() {
        // More elements than a native method's local reference frame holds (-Xcheck:jni warns past it).
        IndexBuffer[] submeshes = new IndexBuffer[200];
        Appearance[] appearances = new Appearance[200];
        for (int i = 0; i < 200; ++i) {
            submeshes[i] = strip();
            appearances[i] = new Appearance();
        }
        Mesh m = new Mesh(vertexBuffer(4), submeshes, appearances);
        assertEquals(200, m.getSubmeshCount());
        assertSame(submeshes[199], m.getIndexBuffer(199));
        assertSame(appearances[123], m.getAppearance(123));
    }

    @Test
    public void setAppearance() {
        Mesh m = new Mesh(vertexBuffer(4), new IndexBuffer[] {strip(), strip()}, null);
        Appearance a = new Appearance();
        m.setAppearance(1, a);
        assertNull(m.getAppearance(0));
        assertSame(a, m.getAppearance(1));
        m.setAppearance(1, null);
        assertNull(m.getAppearance(1));
    }

    @Test
    public void constructorNulls() {
        VertexBuffer vb = vertexBuffer(4);
        assertThrowsExactly(NullPointerException.class, () -> new Mesh(null, strip(), null));
        assertThrowsExactly(NullPointerException.class, () -> new Mesh(vb, (IndexBuffer) null, null));
        assertThrowsExactly(NullPointerException.class, () -> new Mesh(null, new IndexBuffer[] {strip()}, null));
        assertThrowsExactly(NullPointerException.class, () -> new Mesh(vb, (IndexBuffer[]) null, null));
        assertThrowsExactly(NullPointerException.class,
                () -> new Mesh(vb, new IndexBuffer[] {strip(), null}, null));
    }

    @Test
    public void constructorIllegalArguments() {
        VertexBuffer vb = vertexBuffer(4);
        // An empty array is empty, not null.
        assertThrowsExactly(IllegalArgumentException.class, () -> new Mesh(vb, new IndexBuffer[0], null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Mesh(vb, new IndexBuffer[] {strip(), strip()}, new Appearance[1]));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Mesh(vb, new IndexBuffer[] {strip()}, new Appearance[0]));
    }

    @Test
    public void submeshIndices() {
        Mesh m = new Mesh(vertexBuffer(4), new IndexBuffer[] {strip(), strip()}, null);
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getAppearance(-1));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getAppearance(2));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.setAppearance(2, new Appearance()));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.setAppearance(-1, null));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getIndexBuffer(2));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> m.getIndexBuffer(-1));
    }

    @Test
    public void duplicateSharesBuffersAndAppearances() {
        VertexBuffer vb = vertexBuffer(4);
        TriangleStripArray ib = strip();
        Appearance a = new Appearance();
        Mesh m = new Mesh(vb, ib, a);
        Object3D copy = m.duplicate();
        assertTrue(copy instanceof Mesh);
        assertNotSame(m, copy);
        Mesh c = (Mesh) copy;
        assertSame(vb, c.getVertexBuffer());
        assertSame(ib, c.getIndexBuffer(0));
        assertSame(a, c.getAppearance(0));
    }

    @Test
    public void peersForObjectsOnlyTheMeshHolds() throws InterruptedException {
        // The first peers may be collected; the getters then make new ones of the right classes.
        Mesh m = new Mesh(vertexBuffer(4), strip(), new Appearance());
        for (int i = 0; i < 3; ++i) {
            System.gc();
            Thread.sleep(10);
        }
        VertexBuffer vb = m.getVertexBuffer();
        assertEquals(4, vb.getVertexCount());
        VertexArray positions = vb.getPositions(null);
        assertEquals(3, positions.getComponentCount());
        IndexBuffer ib = m.getIndexBuffer(0);
        assertTrue(ib instanceof TriangleStripArray);
        assertEquals(6, ib.getIndexCount());
        assertEquals(0, m.getAppearance(0).getLayer());
        assertSame(vb, m.getVertexBuffer());
    }

    @Test
    public void referencesKeepTheirPeers() {
        // Objects reached only through the mesh come back as the same Java objects.
        Mesh m = new Mesh(vertexBuffer(4), strip(), new Appearance());
        VertexBuffer vb = m.getVertexBuffer();
        IndexBuffer ib = m.getIndexBuffer(0);
        Appearance a = m.getAppearance(0);
        System.gc();
        assertSame(vb, m.getVertexBuffer());
        assertSame(ib, m.getIndexBuffer(0));
        assertSame(a, m.getAppearance(0));
        Object3D[] refs = new Object3D[m.getReferences(null)];
        m.getReferences(refs);
        assertSame(vb, refs[0]);
        assertSame(ib, refs[1]);
        assertSame(a, refs[2]);
    }
}
