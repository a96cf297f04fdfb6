package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;

import org.junit.Test;

/** JSR-184 1.1 World: active camera and background, their identity, the exceptions. */
public class WorldTest {
    @Test
    public void defaults() {
        World w = new World();
        assertNull(w.getActiveCamera());
        assertNull(w.getBackground());
        assertEquals(0, w.getChildCount());
    }

    @Test
    public void cameraAndBackgroundAreTheSamePeers() {
        World w = new World();
        Camera c = new Camera();
        w.addChild(c);
        w.setActiveCamera(c);
        assertSame(c, w.getActiveCamera());
        assertSame(c, w.getChild(0));
        Background b = new Background();
        w.setBackground(b);
        assertSame(b, w.getBackground());
        w.setBackground(null);
        assertNull(w.getBackground());
        Camera other = new Camera();  // need not be in the world
        w.setActiveCamera(other);
        assertSame(other, w.getActiveCamera());
    }

    @Test
    public void duplicateKeepsCameraAndBackground() {
        World w = new World();
        Camera c = new Camera();
        w.addChild(c);
        w.setActiveCamera(c);
        Background b = new Background();
        w.setBackground(b);
        World copy = (World) w.duplicate();
        assertNotNull(copy.getActiveCamera());
        assertNotSame(c, copy.getActiveCamera());
        assertSame(copy.getChild(0), copy.getActiveCamera());
        assertNotNull(copy.getBackground());
    }

    @Test(expected = NullPointerException.class)
    public void nullActiveCamera() {
        new World().setActiveCamera(null);
    }

    @Test(expected = IllegalArgumentException.class)
    public void worldIsNeverAChild() {
        new World().addChild(new World());
    }
}
