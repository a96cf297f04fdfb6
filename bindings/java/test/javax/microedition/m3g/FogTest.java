package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 Fog: defaults, setters and the specified exceptions. */
public class FogTest {
    private static final float EPS = 0.0f;

    @Test
    public void defaults() {
        Fog f = new Fog();
        assertEquals(Fog.LINEAR, f.getMode());
        assertEquals(0x000000, f.getColor());
        assertEquals(1.0f, f.getDensity(), EPS);
        assertEquals(0.0f, f.getNearDistance(), EPS);
        assertEquals(1.0f, f.getFarDistance(), EPS);
        assertEquals(80, Fog.EXPONENTIAL);
        assertEquals(81, Fog.LINEAR);
    }

    @Test
    public void setters() {
        Fog f = new Fog();
        f.setMode(Fog.EXPONENTIAL);
        assertEquals(Fog.EXPONENTIAL, f.getMode());
        f.setLinear(10f, 2f);  // any values
        assertEquals(10f, f.getNearDistance(), EPS);
        assertEquals(2f, f.getFarDistance(), EPS);
        f.setLinear(-5f, -5f);
        assertEquals(-5f, f.getNearDistance(), EPS);
        assertEquals(-5f, f.getFarDistance(), EPS);
        f.setDensity(0f);
        assertEquals(0f, f.getDensity(), EPS);
        f.setDensity(3.5f);
        assertEquals(3.5f, f.getDensity(), EPS);
        f.setColor(0xFF123456);
        assertEquals(0x00123456, f.getColor());  // the top byte is cleared
    }

    @Test
    public void illegalArguments() {
        Fog f = new Fog();
        assertThrowsExactly(IllegalArgumentException.class, () -> f.setMode(82));
        assertThrowsExactly(IllegalArgumentException.class, () -> f.setMode(0));
        assertThrowsExactly(IllegalArgumentException.class, () -> f.setDensity(-0.5f));
        assertEquals(Fog.LINEAR, f.getMode());
        assertEquals(1.0f, f.getDensity(), EPS);
    }

    @Test
    public void duplicate() {
        Fog f = new Fog();
        f.setMode(Fog.EXPONENTIAL);
        f.setDensity(0.25f);
        Object3D copy = f.duplicate();
        assertTrue(copy instanceof Fog);
        assertEquals(Fog.EXPONENTIAL, ((Fog) copy).getMode());
        assertEquals(0.25f, ((Fog) copy).getDensity(), EPS);
    }
}
