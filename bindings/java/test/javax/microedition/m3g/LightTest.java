package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 Light: defaults, setters and the ranges the specification sets. */
public class LightTest {
    @Test
    public void constants() {
        assertEquals(128, Light.AMBIENT);
        assertEquals(129, Light.DIRECTIONAL);
        assertEquals(130, Light.OMNI);
        assertEquals(131, Light.SPOT);
    }

    @Test
    public void defaults() {
        Light l = new Light();
        assertEquals(Light.DIRECTIONAL, l.getMode());
        assertEquals(0xFFFFFF, l.getColor());
        assertEquals(1.0f, l.getIntensity(), 0);
        assertEquals(1.0f, l.getConstantAttenuation(), 0);
        assertEquals(0.0f, l.getLinearAttenuation(), 0);
        assertEquals(0.0f, l.getQuadraticAttenuation(), 0);
        assertEquals(45.0f, l.getSpotAngle(), 0);
        assertEquals(0.0f, l.getSpotExponent(), 0);
    }

    @Test
    public void settersRoundTrip() {
        Light l = new Light();
        for (int mode : new int[] {Light.AMBIENT, Light.OMNI, Light.SPOT, Light.DIRECTIONAL}) {
            l.setMode(mode);
            assertEquals(mode, l.getMode());
        }
        l.setColor(0x123456);
        assertEquals(0x123456, l.getColor());
        l.setColor(0xFF654321);  // the top byte is ignored
        assertEquals(0x654321, l.getColor());
        l.setIntensity(-2.5f);
        assertEquals(-2.5f, l.getIntensity(), 0);
        l.setSpotAngle(0);
        assertEquals(0f, l.getSpotAngle(), 0);
        l.setSpotAngle(90);
        assertEquals(90f, l.getSpotAngle(), 0);
        l.setSpotExponent(128);
        assertEquals(128f, l.getSpotExponent(), 0);
        l.setAttenuation(0, 0.5f, 0.25f);
        assertEquals(0f, l.getConstantAttenuation(), 0);
        assertEquals(0.5f, l.getLinearAttenuation(), 0);
        assertEquals(0.25f, l.getQuadraticAttenuation(), 0);
    }

    @Test
    public void badMode() {
        Light l = new Light();
        for (int mode : new int[] {0, 127, 132}) {
            try {
                l.setMode(mode);
                fail("setMode(" + mode + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        assertEquals(Light.DIRECTIONAL, l.getMode());
    }

    @Test
    public void spotRanges() {
        Light l = new Light();
        for (float a : new float[] {-0.5f, 90.5f}) {
            try {
                l.setSpotAngle(a);
                fail("setSpotAngle(" + a + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        for (float e : new float[] {-0.5f, 128.5f}) {
            try {
                l.setSpotExponent(e);
                fail("setSpotExponent(" + e + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        assertEquals(45f, l.getSpotAngle(), 0);
        assertEquals(0f, l.getSpotExponent(), 0);
    }

    @Test
    public void badAttenuation() {
        Light l = new Light();
        float[][] bad = {{0, 0, 0}, {-1, 1, 1}, {1, -1, 1}, {1, 1, -1}};
        for (float[] a : bad) {
            try {
                l.setAttenuation(a[0], a[1], a[2]);
                fail("setAttenuation(" + a[0] + ", " + a[1] + ", " + a[2] + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        assertEquals(1f, l.getConstantAttenuation(), 0);
    }

    @Test
    public void duplicateCopiesTheSettings() {
        Light l = new Light();
        l.setMode(Light.SPOT);
        l.setColor(0x102030);
        l.setSpotAngle(30);
        Light copy = (Light) l.duplicate();
        assertEquals(Light.SPOT, copy.getMode());
        assertEquals(0x102030, copy.getColor());
        assertEquals(30f, copy.getSpotAngle(), 0);
    }
}
