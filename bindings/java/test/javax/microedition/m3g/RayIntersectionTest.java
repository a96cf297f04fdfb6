package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.appearance;
import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static javax.microedition.m3g.SceneTestSupport.image;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import org.junit.Test;

/**
 * JSR-184 1.1 RayIntersection: defaults, the exceptions, and a pick that
 * fills it (a scaled Sprite3D, skipped while Image2D and Appearance are
 * placeholders).
 */
public class RayIntersectionTest {
    @Test
    public void defaults() {
        RayIntersection ri = new RayIntersection();
        assertNull(ri.getIntersected());
        assertEquals(0f, ri.getDistance(), 0);
        assertEquals(0, ri.getSubmeshIndex());
        assertEquals(0f, ri.getTextureS(0), 0);
        assertEquals(0f, ri.getTextureT(1), 0);
        assertEquals(0f, ri.getNormalX(), 0);
        assertEquals(0f, ri.getNormalY(), 0);
        assertEquals(1f, ri.getNormalZ(), 0);
        float[] ray = {9, 9, 9, 9, 9, 9, 9};
        ri.getRay(ray);
        assertArray(new float[] {0, 0, 0, 0, 0, 1, 9}, ray, 0);
    }

    @Test
    public void textureUnitOutOfBounds() {
        RayIntersection ri = new RayIntersection();
        // numTextureUnits is 2 in m3g-vk's default limits.
        for (int unit : new int[] {-1, 2}) {
            try {
                ri.getTextureS(unit);
                fail("getTextureS(" + unit + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
            try {
                ri.getTextureT(unit);
                fail("getTextureT(" + unit + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
        }
    }

    @Test(expected = NullPointerException.class)
    public void nullRay() {
        new RayIntersection().getRay(null);
    }

    @Test
    public void shortRay() {
        for (float[] a : new float[][] {new float[0], new float[5]}) {
            try {
                new RayIntersection().getRay(a);
                fail("getRay(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test
    public void manyAreCollected() {
        for (int i = 0; i < 20000; i++) {
            new RayIntersection();
        }
        System.gc();
    }

    /** A camera at the origin looking down -Z at a scaled sprite 5 units away. */
    private static Group spriteScene(Camera camera, Sprite3D sprite) {
        Group g = new Group();
        camera.setPerspective(60, 1, 1, 11);
        sprite.setTranslation(0, 0, -6);
        g.addChild(camera);
        g.addChild(sprite);
        return g;
    }

    @Test
    public void pickFillsItWithTheSpritePeer() {
        Camera camera = new Camera();
        Sprite3D sprite = new Sprite3D(true, image(8, 8), appearance());
        Group g = spriteScene(camera, sprite);
        RayIntersection ri = new RayIntersection();
        assertTrue(g.pick(-1, 0.5f, 0.5f, camera, ri));
        assertSame(sprite, ri.getIntersected());
        assertSame(sprite, ri.getIntersected());
        assertEquals(0.5f, ri.getDistance(), 1e-4f);  // halfway from near (1) to far (11)
        assertEquals(0, ri.getSubmeshIndex());
        assertEquals(0.5f, ri.getTextureS(0), 1e-3f);
        assertEquals(0.5f, ri.getTextureT(0), 1e-3f);
        assertEquals(1f, ri.getNormalZ(), 0);
        float[] ray = new float[6];
        ri.getRay(ray);
        assertArray(new float[] {0, 0, -1, 0, 0, -10}, ray, 1e-4f);
        // A miss leaves the result as it was.
        sprite.setPickingEnable(false);
        assertFalse(g.pick(-1, 0.5f, 0.5f, camera, ri));
        assertSame(sprite, ri.getIntersected());
        // The node stays reachable through the result alone.
        g.removeChild(sprite);
        sprite = null;
        System.gc();
        assertTrue(ri.getIntersected() instanceof Sprite3D);
    }

    @Test
    public void scopeMasksTheSprite() {
        Camera camera = new Camera();
        Sprite3D sprite = new Sprite3D(true, image(8, 8), appearance());
        Group g = spriteScene(camera, sprite);
        sprite.setScope(2);
        assertFalse(g.pick(1, 0.5f, 0.5f, camera, null));
        assertTrue(g.pick(3, 0.5f, 0.5f, camera, null));
    }
}
