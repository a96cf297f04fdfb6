package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.EPS;
import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static javax.microedition.m3g.SceneTestSupport.identity;
import static javax.microedition.m3g.SceneTestSupport.matrix;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 Node (through Group, Camera and Light): enables, alpha, scope, alignment, getTransformTo. */
public class NodeTest {
    @Test
    public void constants() {
        assertEquals(144, Node.NONE);
        assertEquals(145, Node.ORIGIN);
        assertEquals(146, Node.X_AXIS);
        assertEquals(147, Node.Y_AXIS);
        assertEquals(148, Node.Z_AXIS);
    }

    @Test
    public void defaults() {
        Node n = new Light();
        assertNull(n.getParent());
        assertEquals(1.0f, n.getAlphaFactor(), 0);
        assertTrue(n.isRenderingEnabled());
        assertTrue(n.isPickingEnabled());
        assertEquals(-1, n.getScope());
        assertEquals(Node.NONE, n.getAlignmentTarget(Node.Z_AXIS));
        assertEquals(Node.NONE, n.getAlignmentTarget(Node.Y_AXIS));
        assertNull(n.getAlignmentReference(Node.Z_AXIS));
        assertNull(n.getAlignmentReference(Node.Y_AXIS));
    }

    @Test
    public void settersRoundTrip() {
        Node n = new Camera();
        n.setAlphaFactor(0.25f);
        assertEquals(0.25f, n.getAlphaFactor(), 0);
        n.setAlphaFactor(0);
        assertEquals(0f, n.getAlphaFactor(), 0);
        n.setAlphaFactor(1);
        n.setRenderingEnable(false);
        assertFalse(n.isRenderingEnabled());
        n.setPickingEnable(false);
        assertFalse(n.isPickingEnabled());
        n.setRenderingEnable(true);
        assertTrue(n.isRenderingEnabled());
        n.setScope(0x5A);
        assertEquals(0x5A, n.getScope());
        n.setScope(0);
        assertEquals(0, n.getScope());
    }

    @Test
    public void parentIsTheGroupPeer() {
        Group g = new Group();
        Light l = new Light();
        g.addChild(l);
        assertSame(g, l.getParent());
        assertSame(g, l.getParent());
        g.removeChild(l);
        assertNull(l.getParent());
    }

    @Test
    public void alignmentReferencesAreTheSamePeers() {
        Group g = new Group();
        Camera c = new Camera();
        Light z = new Light();
        Group y = new Group();
        g.addChild(c);
        g.addChild(z);
        g.addChild(y);
        c.setAlignment(z, Node.ORIGIN, y, Node.Z_AXIS);
        assertSame(z, c.getAlignmentReference(Node.Z_AXIS));
        assertSame(y, c.getAlignmentReference(Node.Y_AXIS));
        assertEquals(Node.ORIGIN, c.getAlignmentTarget(Node.Z_AXIS));
        assertEquals(Node.Z_AXIS, c.getAlignmentTarget(Node.Y_AXIS));
        c.setAlignment(null, Node.X_AXIS, z, Node.NONE);  // a NONE target discards its reference
        assertNull(c.getAlignmentReference(Node.Z_AXIS));
        assertNull(c.getAlignmentReference(Node.Y_AXIS));
        assertEquals(Node.X_AXIS, c.getAlignmentTarget(Node.Z_AXIS));
        assertEquals(Node.NONE, c.getAlignmentTarget(Node.Y_AXIS));
    }

    @Test
    public void alignPointsZAtTheReference() {
        Group g = new Group();
        Camera c = new Camera();
        Light target = new Light();
        target.setTranslation(5, 0, 0);
        g.addChild(c);
        g.addChild(target);
        c.setAlignment(target, Node.ORIGIN, null, Node.NONE);
        g.align(null);
        Transform t = new Transform();
        c.getCompositeTransform(t);
        float[] z = {0, 0, 1, 0};
        t.transform(z);
        assertArray(new float[] {1, 0, 0, 0}, z, 1e-5f);
        // A null reference means the argument of align().
        c.setAlignment(null, Node.ORIGIN, null, Node.NONE);
        target.setTranslation(0, 3, 0);
        c.align(target);
        c.getCompositeTransform(t);
        float[] z2 = {0, 0, 1, 0};
        t.transform(z2);
        assertArray(new float[] {0, 1, 0, 0}, z2, 1e-5f);
    }

    @Test(expected = IllegalStateException.class)
    public void alignNullReferenceUnresolved() {
        Camera c = new Camera();
        c.setAlignment(null, Node.ORIGIN, null, Node.NONE);
        c.align(null);
    }

    @Test(expected = IllegalArgumentException.class)
    public void alignReferenceInAnotherGraph() {
        new Camera().align(new Group());
    }

    @Test(expected = IllegalStateException.class)
    public void alignToOwnDescendant() {
        Group g = new Group();
        Light child = new Light();
        g.addChild(child);
        g.setAlignment(child, Node.ORIGIN, null, Node.NONE);
        g.align(null);
    }

    @Test(expected = IllegalArgumentException.class)
    public void alignmentToItself() {
        Camera c = new Camera();
        c.setAlignment(c, Node.ORIGIN, null, Node.NONE);
    }

    @Test(expected = IllegalArgumentException.class)
    public void alignmentBadTarget() {
        new Camera().setAlignment(null, 143, null, Node.NONE);
    }

    @Test(expected = IllegalArgumentException.class)
    public void alignmentSameReferenceAndTarget() {
        Light l = new Light();
        new Camera().setAlignment(l, Node.Y_AXIS, l, Node.Y_AXIS);
    }

    @Test
    public void alignmentAxisMustBeYOrZ() {
        Node n = new Group();
        for (int axis : new int[] {Node.NONE, Node.ORIGIN, Node.X_AXIS, 0}) {
            try {
                n.getAlignmentTarget(axis);
                fail("getAlignmentTarget(" + axis + ")");
            } catch (IllegalArgumentException expected) {
            }
            try {
                n.getAlignmentReference(axis);
                fail("getAlignmentReference(" + axis + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test
    public void alphaFactorRange() {
        Node n = new Group();
        for (float a : new float[] {-0.01f, 1.01f, Float.NaN}) {
            try {
                n.setAlphaFactor(a);
                fail("setAlphaFactor(" + a + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        assertEquals(1.0f, n.getAlphaFactor(), 0);
    }

    @Test
    public void transformTo() {
        Group root = new Group();
        Group a = new Group();
        Light b = new Light();
        root.addChild(a);
        root.addChild(b);
        a.setTranslation(1, 2, 3);
        b.setTranslation(0, 0, 10);
        Transform t = new Transform();
        assertTrue(a.getTransformTo(root, t));
        assertArray(new float[] {1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}, matrix(t), EPS);
        assertTrue(a.getTransformTo(b, t));
        assertArray(new float[] {1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, -7, 0, 0, 0, 1}, matrix(t), EPS);
        assertTrue(a.getTransformTo(a, t));
        assertArray(identity(), matrix(t), EPS);
    }

    @Test
    public void transformToAnotherGraphLeavesTheTransform() {
        Transform t = new Transform();
        t.postScale(2, 2, 2);
        float[] before = matrix(t);
        assertFalse(new Group().getTransformTo(new Light(), t));
        assertArray(before, matrix(t), 0);
    }

    @Test(expected = NullPointerException.class)
    public void transformToNullTarget() {
        new Group().getTransformTo(null, new Transform());
    }

    @Test(expected = NullPointerException.class)
    public void transformToNullTransform() {
        Group g = new Group();
        g.getTransformTo(g, null);
    }

    @Test(expected = ArithmeticException.class)
    public void transformToSingular() {
        Group root = new Group();
        Group a = new Group();
        Group b = new Group();
        root.addChild(a);
        root.addChild(b);
        b.setScale(0, 1, 1);
        a.getTransformTo(b, new Transform());
    }
}
