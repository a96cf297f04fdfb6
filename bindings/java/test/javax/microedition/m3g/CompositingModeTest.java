package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 CompositingMode: defaults, setters and the specified exceptions. */
public class CompositingModeTest {
    private static final float EPS = 0.0f;

    @Test
    public void defaults() {
        CompositingMode c = new CompositingMode();
        assertEquals(CompositingMode.REPLACE, c.getBlending());
        assertEquals(0.0f, c.getAlphaThreshold(), EPS);
        assertTrue(c.isDepthTestEnabled());
        assertTrue(c.isDepthWriteEnabled());
        assertTrue(c.isColorWriteEnabled());
        assertTrue(c.isAlphaWriteEnabled());
        assertEquals(0.0f, c.getDepthOffsetFactor(), EPS);
        assertEquals(0.0f, c.getDepthOffsetUnits(), EPS);
    }

    @Test
    public void constants() {
        assertEquals(64, CompositingMode.ALPHA);
        assertEquals(65, CompositingMode.ALPHA_ADD);
        assertEquals(66, CompositingMode.MODULATE);
        assertEquals(67, CompositingMode.MODULATE_X2);
        assertEquals(68, CompositingMode.REPLACE);
    }

    @Test
    public void setters() {
        CompositingMode c = new CompositingMode();
        for (int mode : new int[] {CompositingMode.ALPHA, CompositingMode.ALPHA_ADD, CompositingMode.MODULATE,
                CompositingMode.MODULATE_X2, CompositingMode.REPLACE}) {
            c.setBlending(mode);
            assertEquals(mode, c.getBlending());
        }
        c.setAlphaThreshold(1f);
        assertEquals(1f, c.getAlphaThreshold(), EPS);
        c.setAlphaThreshold(0.5f);
        assertEquals(0.5f, c.getAlphaThreshold(), EPS);
        c.setDepthTestEnable(false);
        c.setDepthWriteEnable(false);
        c.setColorWriteEnable(false);
        c.setAlphaWriteEnable(false);
        assertFalse(c.isDepthTestEnabled());
        assertFalse(c.isDepthWriteEnabled());
        assertFalse(c.isColorWriteEnabled());
        assertFalse(c.isAlphaWriteEnabled());
        c.setDepthTestEnable(true);
        assertTrue(c.isDepthTestEnabled());
        assertFalse(c.isDepthWriteEnabled());
        c.setDepthOffset(-2.5f, 7f);  // any values
        assertEquals(-2.5f, c.getDepthOffsetFactor(), EPS);
        assertEquals(7f, c.getDepthOffsetUnits(), EPS);
    }

    @Test
    public void illegalArguments() {
        CompositingMode c = new CompositingMode();
        assertThrowsExactly(IllegalArgumentException.class, () -> c.setBlending(63));
        assertThrowsExactly(IllegalArgumentException.class, () -> c.setBlending(69));
        assertThrowsExactly(IllegalArgumentException.class, () -> c.setAlphaThreshold(-0.01f));
        assertThrowsExactly(IllegalArgumentException.class, () -> c.setAlphaThreshold(1.01f));
        assertEquals(CompositingMode.REPLACE, c.getBlending());
        assertEquals(0f, c.getAlphaThreshold(), EPS);
    }

    @Test
    public void duplicate() {
        CompositingMode c = new CompositingMode();
        c.setBlending(CompositingMode.ALPHA);
        c.setDepthOffset(1f, 2f);
        Object3D copy = c.duplicate();
        assertTrue(copy instanceof CompositingMode);
        assertEquals(CompositingMode.ALPHA, ((CompositingMode) copy).getBlending());
        assertEquals(2f, ((CompositingMode) copy).getDepthOffsetUnits(), EPS);
    }
}
