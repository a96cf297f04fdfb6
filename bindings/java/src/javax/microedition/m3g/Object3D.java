package javax.microedition.m3g;

/**
 * JSR-184 1.1 Object3D over m3g-vk: every peer stands for one native object
 * (docs/java.md, "Identity and lifetime").
 */
public abstract class Object3D {
    static {
        Native.ensureLoaded();
    }

    /** The native object; this peer owns one reference to it. */
    final long handle;
    /** The user object, held here too while only this peer holds the native object (UserObjects.h). */
    Object userObjectHold;

    /** Adopts {@code handle} (one reference, given to this peer). */
    Object3D(long handle) {
        this.handle = handle;
        attach();
        Native.CLEANER.register(this, new Release(handle));
    }

    private static final class Release implements Runnable {
        private final long handle;

        Release(long handle) {
            this.handle = handle;
        }

        @Override
        public void run() {
            release(handle);
        }
    }

    private native void attach();

    private static native void release(long handle);

    /** Native objects with a Java peer, live or awaiting release (tests). */
    static native long nativePeerCount();

    public final native int animate(int time);

    public final Object3D duplicate() {
        return duplicateNative();
    }

    private native Object3D duplicateNative();

    public native Object3D find(int userID);

    public native int getReferences(Object3D[] references);

    public native void setUserID(int userID);

    public native int getUserID();

    public void setUserObject(Object userObject) {
        userObjectHold = userObject;
        setUserObjectNative(userObject);
    }

    private native void setUserObjectNative(Object userObject);

    public native Object getUserObject();

    public native void addAnimationTrack(AnimationTrack animationTrack);

    public native AnimationTrack getAnimationTrack(int index);

    public native void removeAnimationTrack(AnimationTrack animationTrack);

    public native int getAnimationTrackCount();
}
