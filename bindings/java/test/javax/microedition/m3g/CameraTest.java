package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.EPS;
import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static javax.microedition.m3g.SceneTestSupport.identity;
import static javax.microedition.m3g.SceneTestSupport.matrix;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 Camera: the three projections, both getProjection forms, the exceptions. */
public class CameraTest {
    @Test
    public void constants() {
        assertEquals(48, Camera.GENERIC);
        assertEquals(49, Camera.PARALLEL);
        assertEquals(50, Camera.PERSPECTIVE);
    }

    @Test
    public void defaultIsGenericIdentity() {
        Camera c = new Camera();
        float[] params = {7, 7, 7, 7};
        assertEquals(Camera.GENERIC, c.getProjection(params));
        assertArray(new float[] {7, 7, 7, 7}, params, 0);  // untouched for GENERIC
        Transform t = new Transform();
        t.postScale(2, 2, 2);
        assertEquals(Camera.GENERIC, c.getProjection(t));
        assertArray(identity(), matrix(t), 0);
        assertEquals(Camera.GENERIC, c.getProjection((Transform) null));
        assertEquals(Camera.GENERIC, c.getProjection((float[]) null));
    }

    @Test
    public void perspective() {
        Camera c = new Camera();
        c.setPerspective(90, 2, 1, 3);
        float[] params = new float[5];
        params[4] = 9;
        assertEquals(Camera.PERSPECTIVE, c.getProjection(params));
        assertArray(new float[] {90, 2, 1, 3, 9}, params, 0);
        Transform t = new Transform();
        assertEquals(Camera.PERSPECTIVE, c.getProjection(t));
        // h = tan(45 deg) = 1: (1/(a h), 1/h, -(f+n)/(f-n), -2fn/(f-n), -1)
        assertArray(new float[] {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0}, matrix(t), EPS);
    }

    @Test
    public void parallel() {
        Camera c = new Camera();
        c.setParallel(4, 0.5f, -1, -5);  // near and far are free
        float[] params = new float[4];
        assertEquals(Camera.PARALLEL, c.getProjection(params));
        assertArray(new float[] {4, 0.5f, -1, -5}, params, 0);
        Transform t = new Transform();
        assertEquals(Camera.PARALLEL, c.getProjection(t));
        // (2/(a H), 2/H, -2/(f-n), -(f+n)/(f-n))
        assertArray(new float[] {1, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, -1.5f, 0, 0, 0, 1}, matrix(t), EPS);
    }

    @Test
    public void genericIsCopied() {
        Camera c = new Camera();
        c.setPerspective(60, 1, 1, 10);
        Transform m = new Transform();
        m.set(new float[] {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
        c.setGeneric(m);
        float[] expected = matrix(m);
        m.setIdentity();
        Transform got = new Transform();
        assertEquals(Camera.GENERIC, c.getProjection(got));
        assertArray(expected, matrix(got), 0);
    }

    @Test(expected = ArithmeticException.class)
    public void zeroDepthPerspective() {
        Camera c = new Camera();
        c.setPerspective(60, 1, 5, 5);
        c.getProjection(new Transform());
    }

    @Test(expected = ArithmeticException.class)
    public void zeroDepthParallel() {
        Camera c = new Camera();
        c.setParallel(1, 1, 2, 2);
        c.getProjection(new Transform());
    }

    @Test
    public void perspectiveArguments() {
        float[][] bad = {{0, 1, 1, 2}, {180, 1, 1, 2}, {-10, 1, 1, 2}, {60, 0, 1, 2}, {60, -1, 1, 2}, {60, 1, 0, 2},
                         {60, 1, -1, 2}, {60, 1, 1, 0}, {60, 1, 1, -2}};
        Camera c = new Camera();
        for (float[] a : bad) {
            try {
                c.setPerspective(a[0], a[1], a[2], a[3]);
                fail("setPerspective(" + a[0] + ", " + a[1] + ", " + a[2] + ", " + a[3] + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        assertEquals(Camera.GENERIC, c.getProjection((float[]) null));
    }

    @Test
    public void parallelArguments() {
        float[][] bad = {{0, 1, 1, 2}, {-1, 1, 1, 2}, {1, 0, 1, 2}, {1, -1, 1, 2}};
        Camera c = new Camera();
        for (float[] a : bad) {
            try {
                c.setParallel(a[0], a[1], a[2], a[3]);
                fail("setParallel(" + a[0] + ", " + a[1] + ", " + a[2] + ", " + a[3] + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test(expected = NullPointerException.class)
    public void nullGeneric() {
        new Camera().setGeneric(null);
    }

    @Test
    public void shortParams() {
        Camera c = new Camera();
        for (float[] a : new float[][] {new float[0], new float[3]}) {
            try {
                c.getProjection(a);
                fail("getProjection(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
        }
    }
}
