package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;

import org.junit.function.ThrowingRunnable;

/** Shared pieces of the geometry and appearance tests (not a test class itself). */
final class GeometryFixtures {
    private GeometryFixtures() {}

    /** Asserts that {@code call} throws exactly {@code type} (the java.lang class, not a subclass). */
    static <T extends Throwable> T assertThrowsExactly(Class<T> type, ThrowingRunnable call) {
        T thrown = assertThrows(type, call);
        assertEquals(type, thrown.getClass());
        return thrown;
    }

    /** A byte array of {@code vertices} vertices with 3 components, vertex i = (i, i + 1, i + 2). */
    static VertexArray positions(int vertices) {
        VertexArray a = new VertexArray(vertices, 3, 1);
        byte[] values = new byte[vertices * 3];
        for (int i = 0; i < values.length; ++i) {
            values[i] = (byte) (i / 3 + i % 3);
        }
        a.set(0, vertices, values);
        return a;
    }

    /** A VertexBuffer with {@code vertices} positions. */
    static VertexBuffer vertexBuffer(int vertices) {
        VertexBuffer vb = new VertexBuffer();
        vb.setPositions(positions(vertices), 1.0f, null);
        return vb;
    }

    /** One strip over vertices 0, 1, 2, 3. */
    static TriangleStripArray strip() {
        return new TriangleStripArray(0, new int[] {4});
    }
}
