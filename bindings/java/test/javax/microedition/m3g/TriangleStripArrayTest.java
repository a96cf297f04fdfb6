package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/**
 * JSR-184 1.1 TriangleStripArray and its IndexBuffer methods: implicit and
 * explicit strips, the triangle list getIndices returns, copies and the
 * specified exceptions.
 */
public class TriangleStripArrayTest {
    @Test
    public void implicitStrips() {
        IndexBuffer ib = new TriangleStripArray(10, new int[] {3, 4});
        assertEquals(9, ib.getIndexCount());
        int[] out = new int[9];
        ib.getIndices(out);
        // Odd triangles of a strip have their 2nd and 3rd index swapped.
        assertArrayEquals(new int[] {10, 11, 12, 13, 14, 15, 14, 16, 15}, out);
    }

    @Test
    public void explicitStrips() {
        TriangleStripArray t = new TriangleStripArray(new int[] {5, 6, 7, 8, 9, 1, 2, 3}, new int[] {5, 3});
        assertEquals(12, t.getIndexCount());
        int[] out = new int[12];
        t.getIndices(out);
        assertArrayEquals(new int[] {5, 6, 7, 6, 8, 7, 7, 8, 9, 1, 2, 3}, out);
        // Indices past the strips' sum are ignored; 0 and 65535 are valid.
        TriangleStripArray ends = new TriangleStripArray(new int[] {0, 65535, 1, -5}, new int[] {3});
        int[] three = new int[3];
        ends.getIndices(three);
        assertArrayEquals(new int[] {0, 65535, 1}, three);
    }

    @Test
    public void constructorsCopyTheirArrays() {
        int[] indices = {1, 2, 3, 4};
        int[] lengths = {4};
        TriangleStripArray t = new TriangleStripArray(indices, lengths);
        indices[0] = 100;
        lengths[0] = 3;
        int[] out = new int[6];
        t.getIndices(out);
        assertArrayEquals(new int[] {1, 2, 3, 2, 4, 3}, out);

        int[] implicitLengths = {3};
        TriangleStripArray i = new TriangleStripArray(0, implicitLengths);
        implicitLengths[0] = 5;
        assertEquals(3, i.getIndexCount());
    }

    @Test
    public void getIndicesLeavesTheRestOfALongerArray() {
        TriangleStripArray t = new TriangleStripArray(0, new int[] {3});
        int[] out = {-1, -1, -1, -1, -1};
        t.getIndices(out);
        assertArrayEquals(new int[] {0, 1, 2, -1, -1}, out);
    }

    @Test
    public void getIndicesExceptions() {
        TriangleStripArray t = new TriangleStripArray(0, new int[] {4});
        assertThrowsExactly(NullPointerException.class, () -> t.getIndices(null));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.getIndices(new int[5]));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.getIndices(new int[0]));
        int[] out = {7, 7, 7, 7, 7};
        assertThrowsExactly(IllegalArgumentException.class, () -> t.getIndices(out));
        assertArrayEquals(new int[] {7, 7, 7, 7, 7}, out);
    }

    @Test
    public void implicitConstructorExceptions() {
        assertThrowsExactly(NullPointerException.class, () -> new TriangleStripArray(0, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(0, new int[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(0, new int[] {3, 2}));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> new TriangleStripArray(-1, new int[] {3}));
        // firstIndex + sum(stripLengths) > 65535, as the specification words it.
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> new TriangleStripArray(65533, new int[] {3}));
        new TriangleStripArray(65532, new int[] {3});
    }

    @Test
    public void explicitConstructorExceptions() {
        assertThrowsExactly(NullPointerException.class, () -> new TriangleStripArray(null, new int[] {3}));
        assertThrowsExactly(NullPointerException.class, () -> new TriangleStripArray(new int[3], null));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(new int[3], new int[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(new int[3], new int[] {2}));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(new int[3], new int[] {4}));
        assertThrowsExactly(IllegalArgumentException.class, () -> new TriangleStripArray(new int[0], new int[] {3}));
        assertThrowsExactly(IndexOutOfBoundsException.class,
                () -> new TriangleStripArray(new int[] {0, -1, 2}, new int[] {3}));
        assertThrowsExactly(IndexOutOfBoundsException.class,
                () -> new TriangleStripArray(new int[] {0, 65536, 2}, new int[] {3}));
    }

    @Test
    public void duplicate() {
        TriangleStripArray t = new TriangleStripArray(new int[] {3, 2, 1}, new int[] {3});
        Object3D copy = t.duplicate();
        assertTrue(copy instanceof TriangleStripArray);
        int[] out = new int[3];
        ((IndexBuffer) copy).getIndices(out);
        assertArrayEquals(new int[] {3, 2, 1}, out);
    }
}
