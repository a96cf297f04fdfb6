package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 AnimationTrack: the constructor's checks, identity of the sequence and controller, animating a node. */
public class AnimationTrackTest {
    @Test
    public void constants() {
        String[] names = {"ALPHA", "AMBIENT_COLOR", "COLOR", "CROP", "DENSITY", "DIFFUSE_COLOR", "EMISSIVE_COLOR",
                          "FAR_DISTANCE", "FIELD_OF_VIEW", "INTENSITY", "MORPH_WEIGHTS", "NEAR_DISTANCE", "ORIENTATION",
                          "PICKABILITY", "SCALE", "SHININESS", "SPECULAR_COLOR", "SPOT_ANGLE", "SPOT_EXPONENT",
                          "TRANSLATION", "VISIBILITY"};
        for (int i = 0; i < names.length; i++) {
            try {
                assertEquals(names[i], 256 + i, AnimationTrack.class.getField(names[i]).getInt(null));
            } catch (ReflectiveOperationException e) {
                throw new AssertionError(names[i], e);
            }
        }
    }

    @Test
    public void sequenceAndControllerAreTheSamePeers() {
        KeyframeSequence k = new KeyframeSequence(2, 3, KeyframeSequence.LINEAR);
        AnimationTrack t = new AnimationTrack(k, AnimationTrack.TRANSLATION);
        assertSame(k, t.getKeyframeSequence());
        assertEquals(AnimationTrack.TRANSLATION, t.getTargetProperty());
        assertNull(t.getController());
        AnimationController c = new AnimationController();
        t.setController(c);
        assertSame(c, t.getController());
        assertSame(c, t.getController());
        t.setController(null);
        assertNull(t.getController());
    }

    @Test
    public void attachedToANode() {
        Group g = new Group();
        AnimationTrack t = new AnimationTrack(new KeyframeSequence(1, 1, KeyframeSequence.LINEAR), AnimationTrack.ALPHA);
        g.addAnimationTrack(t);
        assertEquals(1, g.getAnimationTrackCount());
        assertSame(t, g.getAnimationTrack(0));
        g.removeAnimationTrack(t);
        assertEquals(0, g.getAnimationTrackCount());
    }

    @Test
    public void animatesTheTranslation() {
        KeyframeSequence k = new KeyframeSequence(2, 3, KeyframeSequence.LINEAR);
        k.setKeyframe(0, 0, new float[] {0, 0, 0});
        k.setKeyframe(1, 100, new float[] {10, 20, 30});
        k.setDuration(100);
        AnimationTrack t = new AnimationTrack(k, AnimationTrack.TRANSLATION);
        t.setController(new AnimationController());
        Group root = new Group();
        Light l = new Light();
        root.addChild(l);
        l.addAnimationTrack(t);
        root.animate(50);
        float[] v = new float[3];
        l.getTranslation(v);
        assertArray(new float[] {5, 10, 15}, v, 1e-4f);
    }

    @Test(expected = IllegalStateException.class)
    public void animatingWithoutDuration() {
        KeyframeSequence k = new KeyframeSequence(1, 1, KeyframeSequence.LINEAR);
        AnimationTrack t = new AnimationTrack(k, AnimationTrack.INTENSITY);
        t.setController(new AnimationController());
        Light l = new Light();
        l.addAnimationTrack(t);
        l.animate(0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void propertyNotAnimatableHere() {
        AnimationTrack t =
            new AnimationTrack(new KeyframeSequence(1, 1, KeyframeSequence.LINEAR), AnimationTrack.FIELD_OF_VIEW);
        new Light().addAnimationTrack(t);
    }

    @Test(expected = NullPointerException.class)
    public void nullSequence() {
        new AnimationTrack(null, AnimationTrack.ALPHA);
    }

    @Test
    public void badProperty() {
        KeyframeSequence k = new KeyframeSequence(1, 1, KeyframeSequence.LINEAR);
        for (int p : new int[] {255, 277, 0}) {
            try {
                new AnimationTrack(k, p);
                fail("property " + p);
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test
    public void componentCountMustFitTheProperty() {
        int[][] bad = {{1, AnimationTrack.TRANSLATION}, {2, AnimationTrack.ALPHA}, {3, AnimationTrack.CROP},
                       {2, AnimationTrack.SCALE}, {3, AnimationTrack.ORIENTATION}, {4, AnimationTrack.COLOR}};
        for (int[] b : bad) {
            try {
                new AnimationTrack(new KeyframeSequence(1, b[0], KeyframeSequence.LINEAR), b[1]);
                fail(b[0] + " components for property " + b[1]);
            } catch (IllegalArgumentException expected) {
            }
        }
    }
}
