package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;


/** Shared parts of the scene-graph tests. */
final class SceneTestSupport {
    static final float EPS = 1e-5f;

    private SceneTestSupport() {}

    static void assertArray(float[] expected, float[] actual, float delta) {
        assertEquals("array length", expected.length, actual.length);
        for (int i = 0; i < expected.length; i++) {
            assertEquals("element " + i, expected[i], actual[i], delta);
        }
    }

    /** The row-major matrix of a Transform. */
    static float[] matrix(Transform t) {
        float[] m = new float[16];
        t.get(m);
        return m;
    }

    static float[] identity() {
        return new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    }

    static Image2D image(int width, int height) {
        return new Image2D(Image2D.RGB, width, height);
    }

    static Appearance appearance() {
        return new Appearance();
    }
}
