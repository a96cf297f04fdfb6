package javax.microedition.m3g;

import static javax.microedition.m3g.SceneTestSupport.EPS;
import static javax.microedition.m3g.SceneTestSupport.assertArray;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import org.junit.Test;

/** JSR-184 1.1 KeyframeSequence: the constructor's checks, defaults, keyframes (copied), ranges, exceptions. */
public class KeyframeSequenceTest {
    @Test
    public void constants() {
        assertEquals(176, KeyframeSequence.LINEAR);
        assertEquals(177, KeyframeSequence.SLERP);
        assertEquals(178, KeyframeSequence.SPLINE);
        assertEquals(179, KeyframeSequence.SQUAD);
        assertEquals(180, KeyframeSequence.STEP);
        assertEquals(192, KeyframeSequence.CONSTANT);
        assertEquals(193, KeyframeSequence.LOOP);
    }

    @Test
    public void defaults() {
        KeyframeSequence k = new KeyframeSequence(3, 2, KeyframeSequence.SPLINE);
        assertEquals(3, k.getKeyframeCount());
        assertEquals(2, k.getComponentCount());
        assertEquals(KeyframeSequence.SPLINE, k.getInterpolationType());
        assertEquals(0, k.getDuration());
        assertEquals(KeyframeSequence.CONSTANT, k.getRepeatMode());
        assertEquals(0, k.getValidRangeFirst());
        assertEquals(2, k.getValidRangeLast());
        float[] v = {7, 7};
        assertEquals(0, k.getKeyframe(2, v));
        assertArray(new float[] {0, 0}, v, 0);
    }

    @Test
    public void keyframesAreCopied() {
        KeyframeSequence k = new KeyframeSequence(2, 3, KeyframeSequence.LINEAR);
        float[] value = {1, 2, 3, 99};  // longer than needed: the rest is ignored
        k.setKeyframe(1, 40, value);
        value[0] = 50;
        float[] out = {7, 7, 7, 7};
        assertEquals(40, k.getKeyframe(1, out));
        assertArray(new float[] {1, 2, 3, 7}, out, 0);
        assertEquals(40, k.getKeyframe(1, null));
        assertEquals(0, k.getKeyframe(0, null));
    }

    @Test
    public void quaternionKeyframesAreNormalised() {
        KeyframeSequence k = new KeyframeSequence(1, 4, KeyframeSequence.SLERP);
        k.setKeyframe(0, 0, new float[] {0, 0, 2, 0});
        float[] q = new float[4];
        k.getKeyframe(0, q);
        assertArray(new float[] {0, 0, 1, 0}, q, EPS);
    }

    @Test
    public void rangeDurationRepeat() {
        KeyframeSequence k = new KeyframeSequence(4, 1, KeyframeSequence.STEP);
        k.setValidRange(1, 2);
        assertEquals(1, k.getValidRangeFirst());
        assertEquals(2, k.getValidRangeLast());
        k.setValidRange(3, 0);  // wraps around
        assertEquals(3, k.getValidRangeFirst());
        assertEquals(0, k.getValidRangeLast());
        k.setDuration(1000);
        assertEquals(1000, k.getDuration());
        k.setRepeatMode(KeyframeSequence.LOOP);
        assertEquals(KeyframeSequence.LOOP, k.getRepeatMode());
    }

    @Test
    public void constructorArguments() {
        int[][] bad = {{0, 1, KeyframeSequence.LINEAR}, {1, 0, KeyframeSequence.LINEAR}, {1, 1, 175},
                       {1, 1, KeyframeSequence.CONSTANT}, {1, 3, KeyframeSequence.SLERP}, {1, 5, KeyframeSequence.SQUAD}};
        for (int[] a : bad) {
            try {
                new KeyframeSequence(a[0], a[1], a[2]);
                fail("KeyframeSequence(" + a[0] + ", " + a[1] + ", " + a[2] + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test(expected = NullPointerException.class)
    public void setNullValue() {
        new KeyframeSequence(1, 1, KeyframeSequence.LINEAR).setKeyframe(0, 0, null);
    }

    @Test
    public void keyframeIndexOutOfBounds() {
        KeyframeSequence k = new KeyframeSequence(2, 1, KeyframeSequence.LINEAR);
        for (int i : new int[] {-1, 2}) {
            try {
                k.setKeyframe(i, 0, new float[1]);
                fail("setKeyframe(" + i + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
            try {
                k.getKeyframe(i, new float[1]);
                fail("getKeyframe(" + i + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
        }
    }

    @Test
    public void keyframeArguments() {
        KeyframeSequence k = new KeyframeSequence(2, 2, KeyframeSequence.LINEAR);
        try {
            k.setKeyframe(0, -1, new float[2]);
            fail("negative time");
        } catch (IllegalArgumentException expected) {
        }
        for (float[] a : new float[][] {new float[0], new float[1]}) {
            try {
                k.setKeyframe(0, 0, a);
                fail("setKeyframe(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
            try {
                k.getKeyframe(0, a);
                fail("getKeyframe(float[" + a.length + "])");
            } catch (IllegalArgumentException expected) {
            }
        }
    }

    @Test
    public void validRangeOutOfBounds() {
        KeyframeSequence k = new KeyframeSequence(3, 1, KeyframeSequence.LINEAR);
        int[][] bad = {{-1, 0}, {0, 3}, {3, 0}, {0, -1}};
        for (int[] r : bad) {
            try {
                k.setValidRange(r[0], r[1]);
                fail("setValidRange(" + r[0] + ", " + r[1] + ")");
            } catch (IndexOutOfBoundsException expected) {
            }
        }
    }

    @Test
    public void durationAndRepeatArguments() {
        KeyframeSequence k = new KeyframeSequence(1, 1, KeyframeSequence.LINEAR);
        for (int d : new int[] {0, -5}) {
            try {
                k.setDuration(d);
                fail("setDuration(" + d + ")");
            } catch (IllegalArgumentException expected) {
            }
        }
        try {
            k.setRepeatMode(KeyframeSequence.LINEAR);
            fail("setRepeatMode(LINEAR)");
        } catch (IllegalArgumentException expected) {
        }
    }
}
