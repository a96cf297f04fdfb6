package javax.microedition.m3g;

/**
 * JSR-184 1.1 RayIntersection: a native m3g::RayIntersection that
 * Group.pick fills. The intersected node is held here, as its peer (so
 * getIntersected returns the same object as the scene graph's getters); the
 * native result holds no object and is freed by the Cleaner.
 */
public class RayIntersection {
    static {
        Native.ensureLoaded();
    }

    /** The native m3g::RayIntersection, owned by this object. */
    final long handle;
    /** The picked node; set by Group.pick's native code. */
    Node intersected;

    public RayIntersection() {
        handle = create();
        Native.CLEANER.register(this, new Destroy(handle));
    }

    private static final class Destroy implements Runnable {
        private final long handle;

        Destroy(long handle) {
            this.handle = handle;
        }

        @Override
        public void run() {
            destroy(handle);
        }
    }

    private static native long create();

    private static native void destroy(long handle);

    public Node getIntersected() {
        return intersected;
    }

    public native float getDistance();

    public native int getSubmeshIndex();

    public native float getTextureS(int index);

    public native float getTextureT(int index);

    public native float getNormalX();

    public native float getNormalY();

    public native float getNormalZ();

    public native void getRay(float[] ray);
}
