package javax.microedition.m3g;

import java.lang.ref.Cleaner;

/**
 * Loads libm3g_jni.so once (docs/java.md, "Finding the native library") and
 * owns the Cleaner that releases the native objects of collected peers.
 * Package-private: not part of JSR-184.
 */
final class Native {
    static final Cleaner CLEANER = Cleaner.create();

    static {
        org.m3gvk.NativeLibrary.load(Native.class);
    }

    private Native() {}

    /** Forces the class (and the library) to load. */
    static void ensureLoaded() {}
}
