package javax.microedition.m3g;

/** JSR-184 1.1 Camera over m3g::Camera. */
public class Camera extends Node {
    public static final int GENERIC = 48;
    public static final int PARALLEL = 49;
    public static final int PERSPECTIVE = 50;

    public Camera() {
        super(create());
    }

    Camera(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setPerspective(float fovy, float aspectRatio, float near, float far);

    public native void setParallel(float height, float aspectRatio, float near, float far);

    public native void setGeneric(Transform transform);

    public native int getProjection(Transform transform);

    public native int getProjection(float[] params);
}
