package javax.microedition.m3g;

import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import java.lang.ref.WeakReference;
import org.junit.Test;

/**
 * Identity and lifetime of peers (docs/java.md): one Java object per native
 * object while the program can see it, native objects freed when Java and the
 * scene graph no longer hold them, user objects kept with the native object
 * and collected in cycles through themselves.
 */
public class LifetimeTest {
    /** Collects until the count of native objects with a peer stops falling; returns it. */
    static long settle() throws InterruptedException {
        long last = Long.MAX_VALUE;
        for (int round = 0; round < 50; ++round) {
            System.gc();
            Thread.sleep(20);
            long now = Object3D.nativePeerCount();
            if (now >= last && round > 3) return now;
            last = now;
        }
        return last;
    }

    static boolean collected(WeakReference<?> ref) throws InterruptedException {
        for (int round = 0; round < 50 && ref.get() != null; ++round) {
            System.gc();
            Thread.sleep(10);
        }
        return ref.get() == null;
    }

    @Test
    public void droppedObjectsLeaveNoNativeObjects() throws Exception {
        long before = settle();
        for (int i = 0; i < 100_000; ++i) {
            Background b = new Background();
            b.setColor(i);
        }
        long after = settle();
        System.out.println("native objects held from Java: " + before + " before, " + after
            + " after 100000 Backgrounds were made and dropped");
        assertTrue("native objects grew from " + before + " to " + after, after - before < 1000);
    }

    @Test
    public void userObjectCyclesAreCollected() throws Exception {
        Background self = new Background();
        self.setUserObject(self);
        WeakReference<Background> selfRef = new WeakReference<>(self);
        Object[] holder = new Object[1];
        Background viaHolder = new Background();
        holder[0] = viaHolder;
        viaHolder.setUserObject(holder);
        WeakReference<Background> holderRef = new WeakReference<>(viaHolder);
        self = null;
        viaHolder = null;
        holder = null;
        assertTrue("an object whose user object is itself is collected", collected(selfRef));
        assertTrue("a cycle through the user object is collected", collected(holderRef));
    }

    @Test
    public void userObjectOutlivesThePeerWhileTheGraphHoldsTheObject() throws Exception {
        World world = new World();
        Background b = new Background();
        world.setBackground(b);
        Object payload = new StringBuilder("payload");
        b.setUserObject(payload);
        WeakReference<Background> peer = new WeakReference<>(b);
        b = null;
        assertTrue("the peer alone is collected", collected(peer));
        Background again = world.getBackground();
        assertSame("the user object stays with the native object", payload, again.getUserObject());
        assertSame("identity while the new peer lives", again, world.getBackground());
        world.setBackground(null);
        assertNull(world.getBackground());
    }
}
