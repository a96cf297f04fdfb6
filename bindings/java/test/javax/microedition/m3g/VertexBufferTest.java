package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static javax.microedition.m3g.GeometryFixtures.positions;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 VertexBuffer: defaults, arrays with scale and bias, copies, identity and the specified exceptions. */
public class VertexBufferTest {
    private static final float EPS = 0.0f;

    @Test
    public void defaults() {
        VertexBuffer vb = new VertexBuffer();
        assertEquals(0, vb.getVertexCount());
        assertEquals(0xFFFFFFFF, vb.getDefaultColor());
        assertNull(vb.getPositions(null));
        assertNull(vb.getNormals());
        assertNull(vb.getColors());
        assertNull(vb.getTexCoords(0, null));
        assertNull(vb.getTexCoords(1, new float[4]));
    }

    @Test
    public void positionsScaleBiasAndIdentity() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray p = positions(4);
        float[] bias = {1, 2, 3};
        vb.setPositions(p, 0.5f, bias);
        bias[0] = 99;  // copied at set
        assertEquals(4, vb.getVertexCount());
        float[] scaleBias = {-1, -1, -1, -1, -7};
        assertSame(p, vb.getPositions(scaleBias));
        assertArrayEquals(new float[] {0.5f, 1, 2, 3, -7}, scaleBias, EPS);
        assertSame(p, vb.getPositions(null));

        // A null bias is zeros.
        vb.setPositions(p, 2f, null);
        vb.getPositions(scaleBias);
        assertArrayEquals(new float[] {2f, 0, 0, 0, -7}, scaleBias, EPS);

        // A longer bias: its first three.
        vb.setPositions(p, 1f, new float[] {4, 5, 6, 7});
        vb.getPositions(scaleBias);
        assertArrayEquals(new float[] {1f, 4, 5, 6, -7}, scaleBias, EPS);

        // Removed: no count left.
        vb.setPositions(null, 1f, null);
        assertNull(vb.getPositions(null));
        assertEquals(0, vb.getVertexCount());
    }

    @Test
    public void texCoordsScaleBias() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray t2 = new VertexArray(4, 2, 2);
        float[] bias = {0.25f, 0.5f};
        vb.setTexCoords(0, t2, 3f, bias);
        bias[1] = 9;
        float[] scaleBias = {-1, -1, -1, -1};
        assertSame(t2, vb.getTexCoords(0, scaleBias));
        assertArrayEquals(new float[] {3f, 0.25f, 0.5f, -1}, scaleBias, EPS);

        VertexArray t3 = new VertexArray(4, 3, 1);
        vb.setTexCoords(1, t3, 1f, new float[] {1, 2, 3});
        float[] sb3 = new float[4];
        assertSame(t3, vb.getTexCoords(1, sb3));
        assertArrayEquals(new float[] {1f, 1, 2, 3}, sb3, EPS);
        assertSame(t3, vb.getTexCoords(1, null));

        // No array on the unit: the array is left alone.
        vb.setTexCoords(1, null, 1f, null);
        float[] untouched = {8, 8, 8, 8};
        assertNull(vb.getTexCoords(1, untouched));
        assertArrayEquals(new float[] {8, 8, 8, 8}, untouched, EPS);
    }

    @Test
    public void normalsColorsDefaultColor() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray n = new VertexArray(3, 3, 2);
        VertexArray c3 = new VertexArray(3, 3, 1);
        VertexArray c4 = new VertexArray(3, 4, 1);
        vb.setNormals(n);
        vb.setColors(c3);
        assertSame(n, vb.getNormals());
        assertSame(c3, vb.getColors());
        assertEquals(3, vb.getVertexCount());
        vb.setColors(c4);
        assertSame(c4, vb.getColors());
        vb.setColors(null);
        assertNull(vb.getColors());
        vb.setDefaultColor(0x12345678);
        assertEquals(0x12345678, vb.getDefaultColor());
    }

    @Test
    public void componentCountsAndTypes() {
        VertexBuffer vb = new VertexBuffer();
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setPositions(new VertexArray(4, 2, 1), 1f, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setPositions(new VertexArray(4, 4, 2), 1f, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setNormals(new VertexArray(4, 2, 1)));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setNormals(new VertexArray(4, 4, 1)));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setColors(new VertexArray(4, 3, 2)));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setColors(new VertexArray(4, 2, 1)));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> vb.setTexCoords(0, new VertexArray(4, 4, 1), 1f, null));
    }

    @Test
    public void vertexCountsMustMatch() {
        VertexBuffer vb = new VertexBuffer();
        vb.setPositions(positions(4), 1f, null);
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setNormals(new VertexArray(5, 3, 1)));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setColors(new VertexArray(3, 3, 1)));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> vb.setTexCoords(0, new VertexArray(2, 2, 1), 1f, null));
        // Replacing the only array may change the count.
        vb.setPositions(positions(6), 1f, null);
        assertEquals(6, vb.getVertexCount());
        // Not once there is another.
        vb.setNormals(new VertexArray(6, 3, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setPositions(positions(4), 1f, null));
        assertEquals(6, vb.getVertexCount());
        // Every array removed: no count left.
        vb.setPositions(null, 1f, null);
        vb.setNormals(null);
        assertEquals(0, vb.getVertexCount());
    }

    @Test
    public void shortBiasAndScaleBiasArrays() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray p = positions(4);
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setPositions(p, 1f, new float[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setPositions(p, 1f, new float[0]));
        VertexArray t3 = new VertexArray(4, 3, 1);
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setTexCoords(0, t3, 1f, new float[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.setTexCoords(0, t3, 1f, new float[0]));
        vb.setPositions(p, 1f, null);
        vb.setTexCoords(0, t3, 1f, null);
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.getPositions(new float[3]));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.getPositions(new float[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> vb.getTexCoords(0, new float[3]));
        // Removing an array does not read the bias.
        vb.setPositions(null, 1f, new float[0]);
    }

    @Test
    public void textureUnitIndex() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray t = new VertexArray(4, 2, 1);
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> vb.setTexCoords(-1, t, 1f, null));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> vb.setTexCoords(1000, t, 1f, null));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> vb.getTexCoords(-1, null));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> vb.getTexCoords(1000, new float[4]));
    }

    @Test
    public void duplicateSharesTheArrays() {
        VertexBuffer vb = new VertexBuffer();
        VertexArray p = positions(4);
        vb.setPositions(p, 2f, new float[] {1, 1, 1});
        vb.setDefaultColor(0x11223344);
        Object3D copy = vb.duplicate();
        assertTrue(copy instanceof VertexBuffer);
        VertexBuffer c = (VertexBuffer) copy;
        float[] scaleBias = new float[4];
        assertSame(p, c.getPositions(scaleBias));
        assertArrayEquals(new float[] {2f, 1, 1, 1}, scaleBias, EPS);
        assertEquals(0x11223344, c.getDefaultColor());
    }
}
