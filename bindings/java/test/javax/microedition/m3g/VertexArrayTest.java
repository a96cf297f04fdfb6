package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/**
 * JSR-184 1.1 VertexArray: construction, set/get of bytes and shorts, copies,
 * and the exceptions the specification lists.
 */
public class VertexArrayTest {
    @Test
    public void constructorAndDefaults() {
        VertexArray a = new VertexArray(5, 3, 1);
        assertEquals(5, a.getVertexCount());
        assertEquals(3, a.getComponentCount());
        assertEquals(1, a.getComponentType());
        byte[] values = new byte[15];
        java.util.Arrays.fill(values, (byte) 7);
        a.get(0, 5, values);
        assertArrayEquals(new byte[15], values);

        VertexArray s = new VertexArray(65535, 4, 2);
        assertEquals(65535, s.getVertexCount());
        assertEquals(4, s.getComponentCount());
        assertEquals(2, s.getComponentType());
        assertEquals(2, new VertexArray(1, 2, 2).getComponentCount());
    }

    @Test
    public void constructorRanges() {
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(0, 3, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(65536, 3, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(-1, 3, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(4, 1, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(4, 5, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(4, 3, 0));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(4, 3, 3));
        assertThrowsExactly(IllegalArgumentException.class, () -> new VertexArray(4, 3, 4));
    }

    @Test
    public void bytesRoundTrip() {
        VertexArray a = new VertexArray(4, 2, 1);
        byte[] in = {-128, 127, 1, -1, 2, -2, 3, -3};
        a.set(0, 4, in);
        byte[] out = new byte[8];
        a.get(0, 4, out);
        assertArrayEquals(in, out);
        // A sub-range.
        a.set(1, 2, new byte[] {10, 11, 12, 13});
        a.get(0, 4, out);
        assertArrayEquals(new byte[] {-128, 127, 10, 11, 12, 13, 3, -3}, out);
        byte[] part = new byte[4];
        a.get(2, 2, part);
        assertArrayEquals(new byte[] {12, 13, 3, -3}, part);
    }

    @Test
    public void shortsRoundTrip() {
        VertexArray a = new VertexArray(3, 3, 2);
        short[] in = {-32768, 32767, 0, 1, -1, 1000, -1000, 5, 6};
        a.set(0, 3, in);
        short[] out = new short[9];
        a.get(0, 3, out);
        assertArrayEquals(in, out);
        a.set(2, 1, new short[] {7, 8, 9});
        short[] last = new short[3];
        a.get(2, 1, last);
        assertArrayEquals(new short[] {7, 8, 9}, last);
    }

    @Test
    public void zeroVerticesIsAllowed() {
        VertexArray a = new VertexArray(2, 2, 1);
        a.set(2, 0, new byte[0]);
        a.get(0, 0, new byte[0]);
        VertexArray s = new VertexArray(2, 2, 2);
        s.set(0, 0, new short[0]);
        s.get(2, 0, new short[0]);
    }

    @Test
    public void setCopiesTheArray() {
        VertexArray a = new VertexArray(2, 2, 1);
        byte[] in = {1, 2, 3, 4};
        a.set(0, 2, in);
        in[0] = 99;
        byte[] out = new byte[4];
        a.get(0, 2, out);
        assertArrayEquals(new byte[] {1, 2, 3, 4}, out);

        VertexArray s = new VertexArray(2, 2, 2);
        short[] sin = {1, 2, 3, 4};
        s.set(0, 2, sin);
        sin[3] = 99;
        short[] sout = new short[4];
        s.get(0, 2, sout);
        assertArrayEquals(new short[] {1, 2, 3, 4}, sout);
    }

    @Test
    public void longerArraysUseTheirStartAndGetLeavesTheRest() {
        VertexArray a = new VertexArray(3, 2, 1);
        a.set(0, 3, new byte[] {1, 2, 3, 4, 5, 6, 100, 101});
        byte[] out = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
        a.get(1, 1, out);
        assertArrayEquals(new byte[] {3, 4, -1, -1, -1, -1, -1, -1, -1}, out);

        VertexArray s = new VertexArray(2, 3, 2);
        s.set(0, 1, new short[] {1, 2, 3, 4, 5, 6, 7});
        short[] sout = {-1, -1, -1, -1, -1, -1, -1};
        s.get(0, 2, sout);
        assertArrayEquals(new short[] {1, 2, 3, 0, 0, 0, -1}, sout);
    }

    @Test
    public void nullArrays() {
        VertexArray a = new VertexArray(2, 2, 1);
        VertexArray s = new VertexArray(2, 2, 2);
        assertThrowsExactly(NullPointerException.class, () -> a.set(0, 1, (byte[]) null));
        assertThrowsExactly(NullPointerException.class, () -> a.get(0, 1, (byte[]) null));
        assertThrowsExactly(NullPointerException.class, () -> s.set(0, 1, (short[]) null));
        assertThrowsExactly(NullPointerException.class, () -> s.get(0, 1, (short[]) null));
    }

    @Test
    public void wrongComponentType() {
        VertexArray a = new VertexArray(2, 2, 1);
        VertexArray s = new VertexArray(2, 2, 2);
        assertThrowsExactly(IllegalStateException.class, () -> a.set(0, 1, new short[2]));
        assertThrowsExactly(IllegalStateException.class, () -> a.get(0, 1, new short[2]));
        assertThrowsExactly(IllegalStateException.class, () -> s.set(0, 1, new byte[2]));
        assertThrowsExactly(IllegalStateException.class, () -> s.get(0, 1, new byte[2]));
    }

    @Test
    public void ranges() {
        VertexArray a = new VertexArray(4, 2, 1);
        VertexArray s = new VertexArray(4, 2, 2);
        assertThrowsExactly(IllegalArgumentException.class, () -> a.set(0, -1, new byte[8]));
        assertThrowsExactly(IllegalArgumentException.class, () -> s.get(0, -1, new short[8]));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.set(-1, 1, new byte[8]));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.set(3, 2, new byte[8]));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.get(4, 1, new byte[8]));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> s.set(2, 3, new short[8]));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> s.get(-1, 1, new short[8]));
    }

    @Test
    public void shortArraysAreIllegalArguments() {
        VertexArray a = new VertexArray(4, 2, 1);
        VertexArray s = new VertexArray(4, 2, 2);
        assertThrowsExactly(IllegalArgumentException.class, () -> a.set(0, 4, new byte[7]));
        assertThrowsExactly(IllegalArgumentException.class, () -> a.get(0, 2, new byte[3]));
        assertThrowsExactly(IllegalArgumentException.class, () -> s.set(1, 3, new short[5]));
        assertThrowsExactly(IllegalArgumentException.class, () -> s.get(0, 1, new short[1]));
        // An empty array is too short, not null.
        assertThrowsExactly(IllegalArgumentException.class, () -> a.set(0, 1, new byte[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> a.get(0, 1, new byte[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> s.set(0, 1, new short[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> s.get(0, 1, new short[0]));
        // A failed get leaves the array alone.
        byte[] out = {5, 5, 5};
        assertThrowsExactly(IllegalArgumentException.class, () -> a.get(0, 2, out));
        assertArrayEquals(new byte[] {5, 5, 5}, out);
    }

    @Test
    public void duplicateAndIdentity() {
        VertexArray a = new VertexArray(2, 2, 1);
        a.set(0, 2, new byte[] {1, 2, 3, 4});
        Object3D copy = a.duplicate();
        assertTrue(copy instanceof VertexArray);
        VertexArray c = (VertexArray) copy;
        byte[] out = new byte[4];
        c.get(0, 2, out);
        assertArrayEquals(new byte[] {1, 2, 3, 4}, out);
        a.setUserID(7);
        assertSame(a, a.find(7));
    }
}
