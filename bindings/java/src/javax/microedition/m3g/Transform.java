package javax.microedition.m3g;

/**
 * JSR-184 1.1 Transform: a 4x4 float matrix, row-major, kept here as the
 * array the native operations (m3g::Transform) read and write.
 */
public class Transform {
    static {
        Native.ensureLoaded();
    }

    /** The matrix, row-major. */
    final float[] m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    public Transform() {}

    public Transform(Transform transform) {
        set(transform);
    }

    public native void setIdentity();

    public native void set(Transform transform);

    public native void set(float[] matrix);

    public native void get(float[] matrix);

    public native void invert();

    public native void transpose();

    public native void postMultiply(Transform transform);

    public native void postScale(float sx, float sy, float sz);

    public native void postRotate(float angle, float ax, float ay, float az);

    public native void postRotateQuat(float qx, float qy, float qz, float qw);

    public native void postTranslate(float tx, float ty, float tz);

    public native void transform(VertexArray in, float[] out, boolean W);

    public native void transform(float[] vectors);
}
