package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 Group: children, their identity and parents, the exceptions, picking without meshes. */
public class GroupTest {
    @Test
    public void defaults() {
        Group g = new Group();
        assertEquals(0, g.getChildCount());
        assertNull(g.getParent());
    }

    @Test
    public void childrenAreTheSamePeers() {
        Group g = new Group();
        Camera c = new Camera();
        Light l = new Light();
        Group sub = new Group();
        g.addChild(c);
        g.addChild(l);
        g.addChild(sub);
        assertEquals(3, g.getChildCount());
        assertSame(c, g.getChild(0));
        assertSame(l, g.getChild(1));
        assertSame(sub, g.getChild(2));
        assertSame(g.getChild(1), g.getChild(1));
        assertSame(g, sub.getParent());
        g.addChild(l);  // re-adding a child changes nothing
        assertEquals(3, g.getChildCount());
        g.removeChild(l);
        assertEquals(2, g.getChildCount());
        assertNull(l.getParent());
        assertSame(c, g.getChild(0));
        assertSame(sub, g.getChild(1));
        g.removeChild(null);  // ignored
        g.removeChild(new Light());  // not a child: ignored
        assertEquals(2, g.getChildCount());
    }

    @Test
    public void referencesAreTheChildren() {
        Group g = new Group();
        Light l = new Light();
        g.addChild(l);
        Object3D[] refs = new Object3D[g.getReferences(null)];
        assertEquals(1, g.getReferences(refs));
        assertSame(l, refs[0]);
    }

    @Test
    public void childKeepsUserObjectWhileOnlyTheGroupHoldsIt() {
        Group g = new Group();
        Object user = new Object();
        Light l = new Light();
        l.setUserObject(user);
        l.setUserID(7);
        g.addChild(l);
        l = null;
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        Node again = g.getChild(0);
        assertSame(user, again.getUserObject());
        assertEquals(7, again.getUserID());
        assertSame(again, g.find(7));
    }

    @Test
    public void duplicateCopiesTheChildren() {
        Group g = new Group();
        Light l = new Light();
        g.addChild(l);
        Group copy = (Group) g.duplicate();
        assertEquals(1, copy.getChildCount());
        Node c = copy.getChild(0);
        assertTrue(c instanceof Light);
        assertNotSame(l, c);
        assertSame(copy, c.getParent());
        assertSame(g, l.getParent());
    }

    @Test(expected = NullPointerException.class)
    public void addNull() {
        new Group().addChild(null);
    }

    @Test(expected = IllegalArgumentException.class)
    public void addItself() {
        Group g = new Group();
        g.addChild(g);
    }

    @Test(expected = IllegalArgumentException.class)
    public void addWorld() {
        new Group().addChild(new World());
    }

    @Test(expected = IllegalArgumentException.class)
    public void addAncestor() {
        Group a = new Group();
        Group b = new Group();
        a.addChild(b);
        b.addChild(a);
    }

    @Test(expected = IllegalArgumentException.class)
    public void addChildOfAnother() {
        Group a = new Group();
        Group b = new Group();
        Light l = new Light();
        a.addChild(l);
        b.addChild(l);
    }

    @Test
    public void childIndexOutOfBounds() {
        Group g = new Group();
        g.addChild(new Light());
        for (int i : new int[] {-1, 1, Integer.MAX_VALUE}) {
            try {
                g.getChild(i);
                fail("getChild(" + i + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
        }
    }

    @Test
    public void pickWithoutMeshesMisses() {
        Group g = new Group();
        Camera c = new Camera();
        c.setPerspective(60, 1, 1, 100);
        g.addChild(c);
        g.addChild(new Light());
        RayIntersection ri = new RayIntersection();
        assertFalse(g.pick(-1, 0, 0, 10, 0, 0, -1, ri));
        assertFalse(g.pick(-1, 0.5f, 0.5f, c, ri));
        assertFalse(g.pick(-1, 0, 0, 10, 0, 0, -1, null));
        assertFalse(g.pick(-1, 0.5f, 0.5f, c, null));
        assertNull(ri.getIntersected());
        assertEquals(0, ri.getDistance(), 0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void pickZeroDirection() {
        new Group().pick(-1, 0, 0, 0, 0, 0, 0, new RayIntersection());
    }

    @Test(expected = NullPointerException.class)
    public void pickNullCamera() {
        new Group().pick(-1, 0.5f, 0.5f, null, new RayIntersection());
    }

    @Test(expected = IllegalStateException.class)
    public void pickCameraInAnotherGraph() {
        Camera c = new Camera();
        c.setPerspective(60, 1, 1, 100);
        new Group().pick(-1, 0.5f, 0.5f, c, new RayIntersection());
    }
}
