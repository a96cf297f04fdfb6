package javax.microedition.m3g;

/** JSR-184 1.1 Fog over m3g::Fog. */
public class Fog extends Object3D {
    public static final int EXPONENTIAL = 80;
    public static final int LINEAR = 81;

    public Fog() {
        super(create());
    }

    Fog(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setMode(int mode);

    public native int getMode();

    public native void setLinear(float near, float far);

    public native float getNearDistance();

    public native float getFarDistance();

    public native void setDensity(float density);

    public native float getDensity();

    public native void setColor(int RGB);

    public native int getColor();
}
