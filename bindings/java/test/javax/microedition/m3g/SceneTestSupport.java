package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import org.junit.Assume;

/**
 * Shared parts of the scene-graph tests. Image2D and Appearance are made
 * through reflection, so that the tests compile while those classes are
 * still being written; tests that need them are skipped until then.
 */
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

    private static <T> T make(Class<T> cls, Class<?>[] types, Object... args) {
        Constructor<T> ctor;
        try {
            ctor = cls.getConstructor(types);
        } catch (NoSuchMethodException e) {
            Assume.assumeNoException(cls.getSimpleName() + " is not written yet in this tree", e);
            throw new AssertionError(e);
        }
        try {
            return ctor.newInstance(args);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException) {
                throw (RuntimeException) cause;
            }
            throw new AssertionError(cause);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }

    /** new Image2D(Image2D.RGB, width, height), or the test is skipped. */
    static Image2D image(int width, int height) {
        return make(Image2D.class, new Class<?>[] {int.class, int.class, int.class}, 99 /* RGB */, width, height);
    }

    /** new Appearance(), or the test is skipped. */
    static Appearance appearance() {
        return make(Appearance.class, new Class<?>[0]);
    }
}
