package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 Appearance: defaults, components (identity), layer range and texture unit indices. */
public class AppearanceTest {
    @Test
    public void defaults() {
        Appearance a = new Appearance();
        assertEquals(0, a.getLayer());
        assertNull(a.getCompositingMode());
        assertNull(a.getFog());
        assertNull(a.getPolygonMode());
        assertNull(a.getMaterial());
        assertNull(a.getTexture(0));
    }

    @Test
    public void componentsAreTheObjectsSet() {
        Appearance a = new Appearance();
        CompositingMode c = new CompositingMode();
        Fog f = new Fog();
        PolygonMode p = new PolygonMode();
        Material m = new Material();
        Texture2D t = new Texture2D(new Image2D(Image2D.RGB, 4, 4));
        a.setCompositingMode(c);
        a.setFog(f);
        a.setPolygonMode(p);
        a.setMaterial(m);
        a.setTexture(0, t);
        assertSame(c, a.getCompositingMode());
        assertSame(f, a.getFog());
        assertSame(p, a.getPolygonMode());
        assertSame(m, a.getMaterial());
        assertSame(t, a.getTexture(0));

        a.setCompositingMode(null);
        a.setFog(null);
        a.setPolygonMode(null);
        a.setMaterial(null);
        a.setTexture(0, null);
        assertNull(a.getCompositingMode());
        assertNull(a.getFog());
        assertNull(a.getPolygonMode());
        assertNull(a.getMaterial());
        assertNull(a.getTexture(0));
    }

    @Test
    public void layer() {
        Appearance a = new Appearance();
        a.setLayer(-63);
        assertEquals(-63, a.getLayer());
        a.setLayer(63);
        assertEquals(63, a.getLayer());
        assertThrowsExactly(IllegalArgumentException.class, () -> a.setLayer(64));
        assertThrowsExactly(IllegalArgumentException.class, () -> a.setLayer(-64));
        assertEquals(63, a.getLayer());
    }

    @Test
    public void textureUnitIndex() {
        Appearance a = new Appearance();
        Texture2D t = new Texture2D(new Image2D(Image2D.RGB, 4, 4));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.setTexture(-1, t));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.setTexture(1000, t));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.getTexture(-1));
        assertThrowsExactly(IndexOutOfBoundsException.class, () -> a.getTexture(1000));
    }

    @Test
    public void duplicateSharesTheComponents() {
        Appearance a = new Appearance();
        Material m = new Material();
        Texture2D t = new Texture2D(new Image2D(Image2D.RGB, 4, 4));
        a.setMaterial(m);
        a.setTexture(0, t);
        a.setLayer(5);
        Object3D copy = a.duplicate();
        assertTrue(copy instanceof Appearance);
        Appearance c = (Appearance) copy;
        assertSame(m, c.getMaterial());
        assertSame(t, c.getTexture(0));
        assertEquals(5, c.getLayer());
    }

    @Test
    public void componentsSurviveTheirOnlyJavaReference() {
        Appearance a = new Appearance();
        a.setMaterial(new Material());
        a.getMaterial().setUserID(11);
        System.gc();
        assertEquals(11, a.getMaterial().getUserID());
        assertSame(a.getMaterial(), a.find(11));
    }
}
