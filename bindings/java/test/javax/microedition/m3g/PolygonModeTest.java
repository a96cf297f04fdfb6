package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 PolygonMode: defaults, setters and the specified exceptions. */
public class PolygonModeTest {
    @Test
    public void defaults() {
        PolygonMode p = new PolygonMode();
        assertEquals(PolygonMode.CULL_BACK, p.getCulling());
        assertEquals(PolygonMode.SHADE_SMOOTH, p.getShading());
        assertEquals(PolygonMode.WINDING_CCW, p.getWinding());
        assertFalse(p.isTwoSidedLightingEnabled());
        assertFalse(p.isLocalCameraLightingEnabled());
        assertFalse(p.isPerspectiveCorrectionEnabled());
    }

    @Test
    public void constants() {
        assertEquals(160, PolygonMode.CULL_BACK);
        assertEquals(161, PolygonMode.CULL_FRONT);
        assertEquals(162, PolygonMode.CULL_NONE);
        assertEquals(164, PolygonMode.SHADE_FLAT);
        assertEquals(165, PolygonMode.SHADE_SMOOTH);
        assertEquals(168, PolygonMode.WINDING_CCW);
        assertEquals(169, PolygonMode.WINDING_CW);
    }

    @Test
    public void setters() {
        PolygonMode p = new PolygonMode();
        for (int mode : new int[] {PolygonMode.CULL_FRONT, PolygonMode.CULL_NONE, PolygonMode.CULL_BACK}) {
            p.setCulling(mode);
            assertEquals(mode, p.getCulling());
        }
        p.setShading(PolygonMode.SHADE_FLAT);
        assertEquals(PolygonMode.SHADE_FLAT, p.getShading());
        p.setWinding(PolygonMode.WINDING_CW);
        assertEquals(PolygonMode.WINDING_CW, p.getWinding());
        p.setTwoSidedLightingEnable(true);
        p.setLocalCameraLightingEnable(true);
        p.setPerspectiveCorrectionEnable(true);
        assertTrue(p.isTwoSidedLightingEnabled());
        assertTrue(p.isLocalCameraLightingEnabled());
        assertTrue(p.isPerspectiveCorrectionEnabled());
        p.setLocalCameraLightingEnable(false);
        assertFalse(p.isLocalCameraLightingEnabled());
        assertTrue(p.isPerspectiveCorrectionEnabled());
    }

    @Test
    public void illegalArguments() {
        PolygonMode p = new PolygonMode();
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setCulling(163));
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setCulling(PolygonMode.SHADE_FLAT));
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setShading(163));
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setShading(PolygonMode.CULL_BACK));
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setWinding(170));
        assertThrowsExactly(IllegalArgumentException.class, () -> p.setWinding(PolygonMode.SHADE_SMOOTH));
        assertEquals(PolygonMode.CULL_BACK, p.getCulling());
        assertEquals(PolygonMode.SHADE_SMOOTH, p.getShading());
        assertEquals(PolygonMode.WINDING_CCW, p.getWinding());
    }

    @Test
    public void duplicate() {
        PolygonMode p = new PolygonMode();
        p.setCulling(PolygonMode.CULL_NONE);
        Object3D copy = p.duplicate();
        assertTrue(copy instanceof PolygonMode);
        assertEquals(PolygonMode.CULL_NONE, ((PolygonMode) copy).getCulling());
    }
}
