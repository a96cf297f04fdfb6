package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import org.junit.Test;

/**
 * JSR-184 1.1 Image2D: the four constructors (the lcdui Image one takes a
 * BufferedImage here), mutability, set() and the specified exceptions.
 */
public class Image2DTest {
    @Test
    public void constants() {
        assertEquals(96, Image2D.ALPHA);
        assertEquals(97, Image2D.LUMINANCE);
        assertEquals(98, Image2D.LUMINANCE_ALPHA);
        assertEquals(99, Image2D.RGB);
        assertEquals(100, Image2D.RGBA);
    }

    @Test
    public void mutable() {
        Image2D i = new Image2D(Image2D.RGB, 3, 5);
        assertTrue(i.isMutable());
        assertEquals(Image2D.RGB, i.getFormat());
        assertEquals(3, i.getWidth());
        assertEquals(5, i.getHeight());
        byte[] white = new byte[45];
        java.util.Arrays.fill(white, (byte) 0xFF);
        assertArrayEquals(white, i.nativePixels());  // opaque white to start with
        i.set(0, 0, 3, 5, new byte[45]);
        i.set(1, 2, 2, 3, new byte[18]);
        i.set(2, 4, 1, 1, new byte[] {1, 2, 3, 4, 5});  // a longer array: its start
    }

    @Test
    public void setWritesTheRectangleAndCopies() {
        Image2D i = new Image2D(Image2D.LUMINANCE, 3, 3);
        byte[] block = {1, 2, 3, 4};
        i.set(1, 1, 2, 2, block);
        block[0] = 99;
        byte f = (byte) 0xFF;
        assertArrayEquals(new byte[] {f, f, f, f, 1, 2, f, 3, 4}, i.nativePixels());
    }

    @Test
    public void fromPixels() {
        for (int[] fb : new int[][] {{Image2D.ALPHA, 1}, {Image2D.LUMINANCE, 1}, {Image2D.LUMINANCE_ALPHA, 2},
                {Image2D.RGB, 3}, {Image2D.RGBA, 4}}) {
            Image2D i = new Image2D(fb[0], 2, 3, new byte[2 * 3 * fb[1]]);
            assertFalse(i.isMutable());
            assertEquals(fb[0], i.getFormat());
            assertEquals(2, i.getWidth());
            assertEquals(3, i.getHeight());
        }
    }

    @Test
    public void pixelsAreCopied() {
        byte[] pixels = {10, 20, 30, 40, 50, 60};
        Image2D i = new Image2D(Image2D.LUMINANCE_ALPHA, 1, 3, pixels);
        pixels[0] = 0;
        assertArrayEquals(new byte[] {10, 20, 30, 40, 50, 60}, i.nativePixels());
        // A longer array: its start.
        Image2D j = new Image2D(Image2D.ALPHA, 2, 1, new byte[] {7, 8, 9});
        assertArrayEquals(new byte[] {7, 8}, j.nativePixels());
    }

    @Test
    public void paletteIsResolvedAndCopied() {
        byte[] indices = {0, 1, 1, 0};
        byte[] palette = {1, 2, 3, 4, 5, 6};
        Image2D i = new Image2D(Image2D.RGB, 2, 2, indices, palette);
        indices[0] = 1;
        palette[0] = 9;
        assertArrayEquals(new byte[] {1, 2, 3, 4, 5, 6, 4, 5, 6, 1, 2, 3}, i.nativePixels());
        // Past the end of a short palette: zeros.
        Image2D j = new Image2D(Image2D.LUMINANCE, 2, 1, new byte[] {0, 5}, new byte[] {42});
        assertArrayEquals(new byte[] {42, 0}, j.nativePixels());
    }

    @Test
    public void fromPalette() {
        Image2D i = new Image2D(Image2D.RGB, 2, 2, new byte[] {0, 1, 1, 0}, new byte[] {1, 2, 3, 4, 5, 6});
        assertFalse(i.isMutable());
        assertEquals(Image2D.RGB, i.getFormat());
        assertEquals(2, i.getWidth());
        // More than 256 entries: the rest is ignored.
        new Image2D(Image2D.RGBA, 1, 1, new byte[1], new byte[257 * 4 + 1]);
        // An empty palette (every index past its end).
        new Image2D(Image2D.LUMINANCE, 1, 1, new byte[1], new byte[0]);
    }

    @Test
    public void constructorExceptions() {
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(95, 1, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(101, 1, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.RGB, 0, 1));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.RGB, 1, -1));

        assertThrowsExactly(NullPointerException.class, () -> new Image2D(Image2D.RGB, 1, 1, (byte[]) null));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.RGB, 2, 2, new byte[11]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.RGB, 1, 1, new byte[0]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(0, 1, 1, new byte[4]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.ALPHA, 0, 1, new byte[4]));

        assertThrowsExactly(NullPointerException.class, () -> new Image2D(Image2D.RGB, 1, 1, null, new byte[3]));
        assertThrowsExactly(NullPointerException.class, () -> new Image2D(Image2D.RGB, 1, 1, new byte[1], null));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Image2D(Image2D.RGB, 2, 2, new byte[3], new byte[3]));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Image2D(Image2D.RGB, 1, 1, new byte[0], new byte[3]));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Image2D(Image2D.RGB, 1, 1, new byte[1], new byte[4]));
        assertThrowsExactly(IllegalArgumentException.class,
                () -> new Image2D(1234, 1, 1, new byte[1], new byte[4]));
    }

    @Test
    public void setExceptions() {
        Image2D m = new Image2D(Image2D.LUMINANCE_ALPHA, 4, 4);
        assertThrowsExactly(NullPointerException.class, () -> m.set(0, 0, 1, 1, null));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(-1, 0, 1, 1, new byte[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, -1, 1, 1, new byte[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, 0, 0, 1, new byte[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, 0, 1, 0, new byte[2]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(3, 0, 2, 1, new byte[4]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, 2, 1, 3, new byte[6]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, 0, 2, 2, new byte[7]));
        assertThrowsExactly(IllegalArgumentException.class, () -> m.set(0, 0, 1, 1, new byte[0]));

        Image2D immutable = new Image2D(Image2D.RGB, 1, 1, new byte[3]);
        assertThrowsExactly(IllegalStateException.class, () -> immutable.set(0, 0, 1, 1, new byte[3]));
    }

    @Test
    public void fromBufferedImage() {
        BufferedImage argb = new BufferedImage(4, 2, BufferedImage.TYPE_INT_ARGB);
        argb.setRGB(0, 0, 0x80FF0000);
        for (int format : new int[] {Image2D.ALPHA, Image2D.LUMINANCE, Image2D.LUMINANCE_ALPHA, Image2D.RGB,
                Image2D.RGBA}) {
            Image2D i = new Image2D(format, argb);
            assertFalse(i.isMutable());
            assertEquals(format, i.getFormat());
            assertEquals(4, i.getWidth());
            assertEquals(2, i.getHeight());
        }
        BufferedImage rgb = new BufferedImage(2, 8, BufferedImage.TYPE_INT_RGB);
        Image2D alphaFromLuminance = new Image2D(Image2D.ALPHA, rgb);
        assertEquals(8, alphaFromLuminance.getHeight());
        assertEquals(2, alphaFromLuminance.getWidth());
        // Usable as a texture (power-of-two sizes).
        new Texture2D(new Image2D(Image2D.RGBA, new BufferedImage(4, 4, BufferedImage.TYPE_4BYTE_ABGR)));
    }

    @Test
    public void bufferedImagePixelsConverted() {
        // Rows top to bottom: red (alpha 0x80), green / blue, transparent black.
        BufferedImage argb = new BufferedImage(2, 2, BufferedImage.TYPE_INT_ARGB);
        argb.setRGB(0, 0, 0x80FF0000);
        argb.setRGB(1, 0, 0xFF00FF00);
        argb.setRGB(0, 1, 0xFF0000FF);
        byte h = (byte) 0x80;
        byte f = (byte) 0xFF;
        // Luminance as Nokia's M3G implementation computes it (16-bit fixed-point Rec. 601, truncated).
        byte lr = 76;          // 0x4CB2 * 255 >> 16
        byte lg = (byte) 149;  // 0x9691 * 255 >> 16
        byte lb = 29;          // 0x1D3E * 255 >> 16
        assertArrayEquals(new byte[] {f, 0, 0, h, 0, f, 0, f, 0, 0, f, f, 0, 0, 0, 0},
                new Image2D(Image2D.RGBA, argb).nativePixels());
        assertArrayEquals(new byte[] {f, 0, 0, 0, f, 0, 0, 0, f, 0, 0, 0},
                new Image2D(Image2D.RGB, argb).nativePixels());
        assertArrayEquals(new byte[] {lr, lg, lb, 0}, new Image2D(Image2D.LUMINANCE, argb).nativePixels());
        assertArrayEquals(new byte[] {lr, h, lg, f, lb, f, 0, 0},
                new Image2D(Image2D.LUMINANCE_ALPHA, argb).nativePixels());
        assertArrayEquals(new byte[] {h, f, f, 0}, new Image2D(Image2D.ALPHA, argb).nativePixels());

        // Without alpha: opaque, and ALPHA is the luminance.
        BufferedImage rgb = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        rgb.setRGB(0, 0, 0xFFFFFF);
        rgb.setRGB(1, 0, 0x00FF00);
        assertArrayEquals(new byte[] {f, lg}, new Image2D(Image2D.ALPHA, rgb).nativePixels());
        assertArrayEquals(new byte[] {f, f, f, f, 0, f, 0, f}, new Image2D(Image2D.RGBA, rgb).nativePixels());
    }

    @Test
    public void fromOtherObjects() {
        BufferedImage image = new BufferedImage(1, 1, BufferedImage.TYPE_INT_ARGB);
        assertThrowsExactly(NullPointerException.class, () -> new Image2D(Image2D.RGB, (Object) null));
        IllegalArgumentException e = assertThrowsExactly(IllegalArgumentException.class,
                () -> new Image2D(Image2D.RGB, (Object) "image.png"));
        assertTrue(e.getMessage(), e.getMessage().contains("java.awt.image.BufferedImage"));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(Image2D.RGB, (Object) new byte[3]));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Image2D(42, image));
    }

    @Test
    public void duplicate() {
        Image2D i = new Image2D(Image2D.RGBA, 2, 2);
        Object3D copy = i.duplicate();
        assertTrue(copy instanceof Image2D);
        Image2D c = (Image2D) copy;
        assertTrue(c.isMutable());
        assertEquals(Image2D.RGBA, c.getFormat());
        assertEquals(2, c.getWidth());
    }
}
