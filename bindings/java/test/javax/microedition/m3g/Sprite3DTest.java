package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.appearance;
import static javax.microedition.m3g.SceneTestSupport.image;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import org.junit.Test;

/**
 * JSR-184 1.1 Sprite3D: the constructor, image and appearance identity, the
 * crop, the exceptions. The tests that need an Image2D or an Appearance are
 * skipped while those classes are placeholders (SceneTestSupport).
 */
public class Sprite3DTest {
    @Test(expected = NullPointerException.class)
    public void nullImage() {
        new Sprite3D(true, null, null);
    }

    @Test
    public void defaults() {
        Image2D img = image(16, 8);
        Sprite3D s = new Sprite3D(true, img, null);
        assertTrue(s.isScaled());
        assertSame(img, s.getImage());
        assertNull(s.getAppearance());
        assertEquals(0, s.getCropX());
        assertEquals(0, s.getCropY());
        assertEquals(16, s.getCropWidth());
        assertEquals(8, s.getCropHeight());
        assertFalse(new Sprite3D(false, img, null).isScaled());
    }

    @Test
    public void imageAndAppearanceAreTheSamePeers() {
        Image2D img = image(4, 4);
        Appearance app = appearance();
        Sprite3D s = new Sprite3D(false, img, app);
        assertSame(app, s.getAppearance());
        assertSame(img, s.getImage());
        Appearance other = appearance();
        s.setAppearance(other);
        assertSame(other, s.getAppearance());
        s.setAppearance(null);
        assertNull(s.getAppearance());
        Object3D[] refs = new Object3D[s.getReferences(null)];
        s.getReferences(refs);
        assertSame(img, refs[0]);
    }

    @Test
    public void setImageResetsTheCrop() {
        Sprite3D s = new Sprite3D(true, image(16, 8), null);
        s.setCrop(-3, 2, -5, 7);  // negative sizes mirror
        assertEquals(-3, s.getCropX());
        assertEquals(2, s.getCropY());
        assertEquals(-5, s.getCropWidth());
        assertEquals(7, s.getCropHeight());
        Image2D other = image(32, 2);
        s.setImage(other);
        assertSame(other, s.getImage());
        assertEquals(0, s.getCropX());
        assertEquals(0, s.getCropY());
        assertEquals(32, s.getCropWidth());
        assertEquals(2, s.getCropHeight());
    }

    @Test
    public void cropTooLarge() {
        Sprite3D s = new Sprite3D(true, image(4, 4), null);
        s.setCrop(0, 0, 1024, -1024);  // maxSpriteCropDimension
        int[][] bad = {{1025, 1}, {1, 1025}, {-1025, 1}, {1, -1025}};
        for (int[] b : bad) {
            try {
                s.setCrop(0, 0, b[0], b[1]);
                fail("setCrop(0, 0, " + b[0] + ", " + b[1] + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test(expected = NullPointerException.class)
    public void setNullImage() {
        new Sprite3D(true, image(4, 4), null).setImage(null);
    }
}
