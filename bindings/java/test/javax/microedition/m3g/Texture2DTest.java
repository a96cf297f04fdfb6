package javax.microedition.m3g;

import static javax.microedition.m3g.GeometryFixtures.assertThrowsExactly;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/**
 * JSR-184 1.1 Texture2D: defaults, image (identity, size rules), filtering,
 * wrapping, blending and the specified exceptions. (Its Transformable
 * methods are Transformable's, tested there.)
 */
public class Texture2DTest {
    private static Image2D image(int width, int height) {
        return new Image2D(Image2D.RGBA, width, height);
    }

    @Test
    public void defaults() {
        Image2D image = image(8, 4);
        Texture2D t = new Texture2D(image);
        assertSame(image, t.getImage());
        assertEquals(0x000000, t.getBlendColor());
        assertEquals(Texture2D.FUNC_MODULATE, t.getBlending());
        assertEquals(Texture2D.WRAP_REPEAT, t.getWrappingS());
        assertEquals(Texture2D.WRAP_REPEAT, t.getWrappingT());
        assertEquals(Texture2D.FILTER_BASE_LEVEL, t.getLevelFilter());
        assertEquals(Texture2D.FILTER_NEAREST, t.getImageFilter());
    }

    @Test
    public void constants() {
        assertEquals(208, Texture2D.FILTER_BASE_LEVEL);
        assertEquals(209, Texture2D.FILTER_LINEAR);
        assertEquals(210, Texture2D.FILTER_NEAREST);
        assertEquals(224, Texture2D.FUNC_ADD);
        assertEquals(225, Texture2D.FUNC_BLEND);
        assertEquals(226, Texture2D.FUNC_DECAL);
        assertEquals(227, Texture2D.FUNC_MODULATE);
        assertEquals(228, Texture2D.FUNC_REPLACE);
        assertEquals(240, Texture2D.WRAP_CLAMP);
        assertEquals(241, Texture2D.WRAP_REPEAT);
    }

    @Test
    public void image() {
        Texture2D t = new Texture2D(image(4, 4));
        Image2D other = new Image2D(Image2D.LUMINANCE, 1, 16, new byte[16]);  // immutable, 1 wide
        t.setImage(other);
        assertSame(other, t.getImage());
        assertThrowsExactly(NullPointerException.class, () -> t.setImage(null));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setImage(image(3, 4)));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setImage(image(4, 6)));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setImage(new Image2D(Image2D.ALPHA, 65536, 1)));
        assertSame(other, t.getImage());
    }

    @Test
    public void constructorExceptions() {
        assertThrowsExactly(NullPointerException.class, () -> new Texture2D(null));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Texture2D(image(5, 4)));
        assertThrowsExactly(IllegalArgumentException.class, () -> new Texture2D(new Image2D(Image2D.ALPHA, 1, 65536)));
    }

    @Test
    public void filtering() {
        Texture2D t = new Texture2D(image(4, 4));
        for (int level : new int[] {Texture2D.FILTER_BASE_LEVEL, Texture2D.FILTER_NEAREST, Texture2D.FILTER_LINEAR}) {
            for (int img : new int[] {Texture2D.FILTER_NEAREST, Texture2D.FILTER_LINEAR}) {
                t.setFiltering(level, img);
                assertEquals(level, t.getLevelFilter());
                assertEquals(img, t.getImageFilter());
            }
        }
        assertThrowsExactly(IllegalArgumentException.class,
                () -> t.setFiltering(Texture2D.FILTER_NEAREST, Texture2D.FILTER_BASE_LEVEL));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setFiltering(207, Texture2D.FILTER_NEAREST));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setFiltering(Texture2D.FILTER_LINEAR, 211));
    }

    @Test
    public void wrapping() {
        Texture2D t = new Texture2D(image(4, 4));
        t.setWrapping(Texture2D.WRAP_CLAMP, Texture2D.WRAP_REPEAT);
        assertEquals(Texture2D.WRAP_CLAMP, t.getWrappingS());
        assertEquals(Texture2D.WRAP_REPEAT, t.getWrappingT());
        t.setWrapping(Texture2D.WRAP_REPEAT, Texture2D.WRAP_CLAMP);
        assertEquals(Texture2D.WRAP_REPEAT, t.getWrappingS());
        assertEquals(Texture2D.WRAP_CLAMP, t.getWrappingT());
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setWrapping(239, Texture2D.WRAP_CLAMP));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setWrapping(Texture2D.WRAP_CLAMP, 242));
    }

    @Test
    public void blending() {
        Texture2D t = new Texture2D(image(4, 4));
        for (int func : new int[] {Texture2D.FUNC_ADD, Texture2D.FUNC_BLEND, Texture2D.FUNC_DECAL,
                Texture2D.FUNC_MODULATE, Texture2D.FUNC_REPLACE}) {
            t.setBlending(func);
            assertEquals(func, t.getBlending());
        }
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setBlending(223));
        assertThrowsExactly(IllegalArgumentException.class, () -> t.setBlending(229));
        t.setBlendColor(0xAB123456);
        assertEquals(0x00123456, t.getBlendColor());  // the top byte is cleared
    }

    @Test
    public void duplicateSharesTheImage() {
        Image2D image = image(4, 4);
        Texture2D t = new Texture2D(image);
        t.setBlending(Texture2D.FUNC_DECAL);
        Object3D copy = t.duplicate();
        assertTrue(copy instanceof Texture2D);
        assertSame(image, ((Texture2D) copy).getImage());
        assertEquals(Texture2D.FUNC_DECAL, ((Texture2D) copy).getBlending());
    }
}
