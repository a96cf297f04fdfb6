package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** JSR-184 1.1 Background: defaults, setters and the exceptions the specification lists. */
public class BackgroundTest {
    @Test
    public void defaults() {
        Background b = new Background();
        assertEquals(0x00000000, b.getColor());
        assertNull(b.getImage());
        assertEquals(Background.BORDER, b.getImageModeX());
        assertEquals(Background.BORDER, b.getImageModeY());
        assertEquals(0, b.getCropX());
        assertEquals(0, b.getCropY());
        assertEquals(0, b.getCropWidth());
        assertEquals(0, b.getCropHeight());
        assertTrue(b.isColorClearEnabled());
        assertTrue(b.isDepthClearEnabled());
    }

    @Test
    public void settersRoundTrip() {
        Background b = new Background();
        b.setColor(0x80FF4020);
        assertEquals(0x80FF4020, b.getColor());
        b.setImageMode(Background.REPEAT, Background.BORDER);
        assertEquals(Background.REPEAT, b.getImageModeX());
        assertEquals(Background.BORDER, b.getImageModeY());
        b.setCrop(-3, 4, 10, 20);
        assertEquals(-3, b.getCropX());
        assertEquals(4, b.getCropY());
        assertEquals(10, b.getCropWidth());
        assertEquals(20, b.getCropHeight());
        b.setColorClearEnable(false);
        b.setDepthClearEnable(false);
        assertFalse(b.isColorClearEnabled());
        assertFalse(b.isDepthClearEnabled());
    }

    @Test(expected = IllegalArgumentException.class)
    public void badImageMode() {
        new Background().setImageMode(31, Background.BORDER);
    }

    @Test(expected = IllegalArgumentException.class)
    public void negativeCropSize() {
        new Background().setCrop(0, 0, -1, 1);
    }

    @Test
    public void userIdAndUserObjectAndIdentity() {
        Background b = new Background();
        b.setUserID(42);
        assertEquals(42, b.getUserID());
        assertSame(b, b.find(42));
        Object o = new Object();
        b.setUserObject(o);
        assertSame(o, b.getUserObject());
        Background copy = (Background) b.duplicate();
        assertSame(o, copy.getUserObject());
        assertEquals(42, copy.getUserID());
        assertSame(copy, copy.find(42));
    }
}
