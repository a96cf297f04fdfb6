package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.EPS;
import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static javax.microedition.m3g.SceneTestSupport.identity;
import static javax.microedition.m3g.SceneTestSupport.matrix;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 Transformable (through Group and Camera): T R S M, the float[] and Transform getters, exceptions. */
public class TransformableTest {
    @Test
    public void defaults() {
        Transformable t = new Group();
        float[] v = {9, 9, 9};
        t.getTranslation(v);
        assertArray(new float[] {0, 0, 0}, v, 0);
        t.getScale(v);
        assertArray(new float[] {1, 1, 1}, v, 0);
        float[] aa = {9, 9, 9, 9};
        t.getOrientation(aa);
        assertEquals(0, aa[0], 0);
        Transform m = new Transform();
        m.postScale(3, 3, 3);
        t.getTransform(m);
        assertArray(identity(), matrix(m), 0);
        m.postScale(3, 3, 3);
        t.getCompositeTransform(m);
        assertArray(identity(), matrix(m), 0);
    }

    @Test
    public void translationAndScale() {
        Transformable t = new Camera();
        t.setTranslation(1, 2, 3);
        t.translate(1, -1, 0.5f);
        float[] v = new float[3];
        t.getTranslation(v);
        assertArray(new float[] {2, 1, 3.5f}, v, EPS);
        t.setScale(2, 3, 4);
        t.scale(0.5f, 2, -1);
        t.getScale(v);
        assertArray(new float[] {1, 6, -4}, v, EPS);
    }

    @Test
    public void longerArraysKeepTheirTail() {
        Transformable t = new Group();
        t.setTranslation(1, 2, 3);
        float[] v = {7, 7, 7, 7, 7};
        t.getTranslation(v);
        assertArray(new float[] {1, 2, 3, 7, 7}, v, 0);
        float[] aa = {7, 7, 7, 7, 7, 7};
        t.setOrientation(90, 0, 0, 2);
        t.getOrientation(aa);
        assertArray(new float[] {90, 0, 0, 1, 7, 7}, aa, 1e-4f);
    }

    @Test
    public void orientation() {
        Transformable t = new Group();
        t.setOrientation(90, 0, 0, 1);
        float[] aa = new float[4];
        t.getOrientation(aa);
        assertArray(new float[] {90, 0, 0, 1}, aa, 1e-4f);
        t.postRotate(90, 0, 0, 1);
        t.getOrientation(aa);
        assertArray(new float[] {180, 0, 0, 1}, aa, 1e-3f);
        t.preRotate(-180, 0, 0, 1);
        t.getOrientation(aa);
        assertEquals(0, aa[0], 1e-3f);
        t.setOrientation(0, 0, 0, 0);  // a zero axis is fine with a zero angle
    }

    @Test
    public void compositeIsTRSM() {
        Transformable t = new Group();
        t.setTranslation(1, 2, 3);
        t.setScale(2, 2, 2);
        Transform m = new Transform();
        m.postTranslate(0, 0, 1);
        t.setTransform(m);
        Transform got = new Transform();
        t.getTransform(got);
        assertArray(matrix(m), matrix(got), 0);
        t.getCompositeTransform(got);
        assertArray(new float[] {2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 5, 0, 0, 0, 1}, matrix(got), EPS);
        t.setTransform(null);
        t.getTransform(got);
        assertArray(identity(), matrix(got), 0);
    }

    @Test
    public void setTransformCopies() {
        Transformable t = new Group();
        Transform m = new Transform();
        m.postTranslate(4, 5, 6);
        t.setTransform(m);
        m.setIdentity();
        Transform got = new Transform();
        t.getTransform(got);
        assertEquals(4, matrix(got)[3], 0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void nodeTransformMustBeAffine() {
        Transform m = new Transform();
        m.set(new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1});
        new Group().setTransform(m);
    }

    @Test(expected = IllegalArgumentException.class)
    public void zeroAxisWithAngle() {
        new Group().setOrientation(10, 0, 0, 0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void zeroAxisPostRotate() {
        new Group().postRotate(10, 0, 0, 0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void zeroAxisPreRotate() {
        new Group().preRotate(10, 0, 0, 0);
    }

    @Test
    public void nullArraysAndTransforms() {
        Transformable t = new Group();
        try {
            t.getOrientation(null);
            fail("getOrientation(null)");
        } catch (NullPointerException expected) {
        }
        try {
            t.getScale(null);
            fail("getScale(null)");
        } catch (NullPointerException expected) {
        }
        try {
            t.getTranslation(null);
            fail("getTranslation(null)");
        } catch (NullPointerException expected) {
        }
        try {
            t.getTransform(null);
            fail("getTransform(null)");
        } catch (NullPointerException expected) {
        }
        try {
            t.getCompositeTransform(null);
            fail("getCompositeTransform(null)");
        } catch (NullPointerException expected) {
        }
    }

    @Test
    public void shortArrays() {
        Transformable t = new Group();
        for (float[] a : new float[][] {new float[0], new float[3]}) {
            try {
                t.getOrientation(a);
                fail("getOrientation(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
        }
        for (float[] a : new float[][] {new float[0], new float[2]}) {
            try {
                t.getScale(a);
                fail("getScale(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
            try {
                t.getTranslation(a);
                fail("getTranslation(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
        }
    }
}
