package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.awt.image.BufferedImage;
import java.util.Hashtable;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.After;
import org.junit.Test;
import org.m3gvk.TargetAdapter;
import org.m3gvk.TargetAdapters;

/** JSR-184 1.1 Graphics3D: targets (BufferedImage, adapters), clears, state and its exceptions. */
public class Graphics3DTest {
    /** An emulator's Graphics stand-in: pixels, a translation and a clip, through an adapter. */
    static final class FakeGraphics {
        final int width, height;
        final int[] argb;
        int tx, ty;
        int[] clip;

        FakeGraphics(int width, int height, int fill) {
            this.width = width;
            this.height = height;
            argb = new int[width * height];
            java.util.Arrays.fill(argb, fill);
            clip = new int[] {0, 0, width, height};
        }
    }

    static final class FakeAdapter implements TargetAdapter {
        @Override
        public int getWidth(Object t) {
            return ((FakeGraphics) t).width;
        }

        @Override
        public int getHeight(Object t) {
            return ((FakeGraphics) t).height;
        }

        @Override
        public int getTranslateX(Object t) {
            return ((FakeGraphics) t).tx;
        }

        @Override
        public int getTranslateY(Object t) {
            return ((FakeGraphics) t).ty;
        }

        @Override
        public int[] getClip(Object t) {
            return ((FakeGraphics) t).clip.clone();
        }

        @Override
        public void readPixels(Object t, int[] argb) {
            System.arraycopy(((FakeGraphics) t).argb, 0, argb, 0, argb.length);
        }

        @Override
        public void writePixels(Object t, int[] argb) {
            System.arraycopy(argb, 0, ((FakeGraphics) t).argb, 0, argb.length);
        }
    }

    @After
    public void unbind() {
        Graphics3D.getInstance().releaseTarget();
        TargetAdapters.unregister(FakeGraphics.class);
    }

    @Test
    public void oneInstancePerThread() throws Exception {
        Graphics3D g = Graphics3D.getInstance();
        assertSame(g, Graphics3D.getInstance());
        AtomicReference<Graphics3D> other = new AtomicReference<>();
        Thread t = new Thread(() -> other.set(Graphics3D.getInstance()));
        t.start();
        t.join();
        assertNotSame(g, other.get());
    }

    @Test
    public void clearsABufferedImage() {
        BufferedImage image = new BufferedImage(40, 30, BufferedImage.TYPE_INT_ARGB);
        Background b = new Background();
        b.setColor(0xFF204080);
        Graphics3D g = Graphics3D.getInstance();
        g.bindTarget(image);
        assertSame(image, g.getTarget());
        assertEquals(40, g.getViewportWidth());
        assertEquals(30, g.getViewportHeight());
        g.clear(b);
        g.releaseTarget();
        assertNull(g.getTarget());
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) assertEquals(0xFF204080, image.getRGB(x, y));
    }

    @Test
    public void adapterTargetKeepsPixelsOutsideItsClipAndTranslation() {
        TargetAdapters.register(FakeGraphics.class, new FakeAdapter());
        FakeGraphics fg = new FakeGraphics(20, 10, 0xFF112233);
        fg.tx = 2;
        fg.ty = 1;
        fg.clip = new int[] {3, 2, 5, 4};  // translated: pixels x 5..9, y 3..6
        Background b = new Background();
        b.setColor(0xFFFF0000);
        Graphics3D g = Graphics3D.getInstance();
        g.bindTarget(fg, false, 0);
        // The viewport is the clip, in the Graphics' translated coordinates.
        assertEquals(3, g.getViewportX());
        assertEquals(2, g.getViewportY());
        assertEquals(5, g.getViewportWidth());
        assertEquals(4, g.getViewportHeight());
        g.clear(b);
        g.releaseTarget();
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 20; ++x) {
                boolean inside = x >= 5 && x < 10 && y >= 3 && y < 7;
                assertEquals("pixel " + x + "," + y, inside ? 0xFFFF0000 : 0xFF112233, fg.argb[y * 20 + x]);
            }
    }

    @Test
    public void targetsAreCheckedAsTheSpecificationSays() {
        Graphics3D g = Graphics3D.getInstance();
        try {
            g.bindTarget(null);
            fail("null target");
        } catch (NullPointerException expected) {
        }
        try {
            g.bindTarget("a string");
            fail("a String target");
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("TargetAdapter"));
        }
        try {
            g.clear(new Background());
            fail("clear without a target");
        } catch (IllegalStateException expected) {
        }
        BufferedImage image = new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB);
        g.bindTarget(image);
        try {
            g.bindTarget(image);
            fail("bound twice");
        } catch (IllegalStateException expected) {
        }
        g.releaseTarget();
    }

    @Test
    public void viewportAndDepthRange() {
        Graphics3D g = Graphics3D.getInstance();
        g.bindTarget(new BufferedImage(16, 16, BufferedImage.TYPE_INT_ARGB));
        g.setViewport(1, 2, 3, 4);
        assertEquals(1, g.getViewportX());
        assertEquals(2, g.getViewportY());
        assertEquals(3, g.getViewportWidth());
        assertEquals(4, g.getViewportHeight());
        g.setDepthRange(0.25f, 0.75f);
        assertEquals(0.25f, g.getDepthRangeNear(), 0f);
        assertEquals(0.75f, g.getDepthRangeFar(), 0f);
        try {
            g.setDepthRange(-0.5f, 1f);
            fail("depth range outside [0, 1]");
        } catch (IllegalArgumentException expected) {
        }
        try {
            g.setViewport(0, 0, 0, 10);
            fail("zero width viewport");
        } catch (IllegalArgumentException expected) {
        }
        g.releaseTarget();
    }

    @Test
    public void propertiesHoldTheSpecificationsKeys() {
        Hashtable<?, ?> p = Graphics3D.getProperties();
        assertEquals(Boolean.class, p.get("supportAntialiasing").getClass());
        assertTrue((Integer) p.get("maxLights") >= 8);
        assertTrue((Integer) p.get("maxTextureDimension") >= 256);
        assertTrue((Integer) p.get("maxTransformsPerVertex") >= 2);
    }

    @Test
    public void lightsNeedALight() {
        Graphics3D g = Graphics3D.getInstance();
        try {
            g.addLight(null, null);
            fail("null light");
        } catch (NullPointerException expected) {
        }
        try {
            g.getLight(0, null);
            fail("no light 0");
        } catch (IndexOutOfBoundsException expected) {
        }
    }
}
