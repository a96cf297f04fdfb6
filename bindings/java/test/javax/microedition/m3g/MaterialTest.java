package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 Material: defaults, colors by target, shininess range, vertex color tracking. */
public class MaterialTest {
    private static final float EPS = 0.0f;

    @Test
    public void defaults() {
        Material m = new Material();
        assertEquals(0x00333333, m.getColor(Material.AMBIENT));
        assertEquals(0xFFCCCCCC, m.getColor(Material.DIFFUSE));
        assertEquals(0x00000000, m.getColor(Material.EMISSIVE));
        assertEquals(0x00000000, m.getColor(Material.SPECULAR));
        assertEquals(0.0f, m.getShininess(), EPS);
        assertFalse(m.isVertexColorTrackingEnabled());
    }

    @Test
    public void constants() {
        assertEquals(1024, Material.AMBIENT);
        assertEquals(2048, Material.DIFFUSE);
        assertEquals(4096, Material.EMISSIVE);
        assertEquals(8192, Material.SPECULAR);
    }

    @Test
    public void colors() {
        Material m = new Material();
        m.setColor(Material.DIFFUSE, 0x80102030);
        assertEquals(0x80102030, m.getColor(Material.DIFFUSE));  // diffuse keeps its alpha
        m.setColor(Material.AMBIENT | Material.EMISSIVE | Material.SPECULAR, 0xFF405060);
        assertEquals(0x00405060, m.getColor(Material.AMBIENT));
        assertEquals(0x00405060, m.getColor(Material.EMISSIVE));
        assertEquals(0x00405060, m.getColor(Material.SPECULAR));
        assertEquals(0x80102030, m.getColor(Material.DIFFUSE));
        m.setColor(Material.AMBIENT | Material.DIFFUSE | Material.EMISSIVE | Material.SPECULAR, 0x11223344);
        assertEquals(0x11223344, m.getColor(Material.DIFFUSE));
        assertEquals(0x00223344, m.getColor(Material.SPECULAR));
    }

    @Test
    public void colorTargets() {
        Material m = new Material();
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setColor(0, 0));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setColor(Material.AMBIENT | 1, 0));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setColor(16384, 0));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getColor(0));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getColor(Material.AMBIENT | Material.DIFFUSE));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.getColor(1));
    }

    @Test
    public void shininess() {
        Material m = new Material();
        m.setShininess(128f);
        assertEquals(128f, m.getShininess(), EPS);
        m.setShininess(12.5f);
        assertEquals(12.5f, m.getShininess(), EPS);
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setShininess(-0.01f));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.setShininess(128.01f));
        assertEquals(12.5f, m.getShininess(), EPS);
    }

    @Test
    public void vertexColorTracking() {
        Material m = new Material();
        m.setVertexColorTrackingEnable(true);
        assertTrue(m.isVertexColorTrackingEnabled());
        m.setVertexColorTrackingEnable(false);
        assertFalse(m.isVertexColorTrackingEnabled());
    }

    @Test
    public void duplicate() {
        Material m = new Material();
        m.setColor(Material.SPECULAR, 0x00ABCDEF);
        m.setShininess(3f);
        Object3D copy = m.duplicate();
        assertTrue(copy instanceof Material);
        assertEquals(0x00ABCDEF, ((Material) copy).getColor(Material.SPECULAR));
        assertEquals(3f, ((Material) copy).getShininess(), EPS);
    }
}
