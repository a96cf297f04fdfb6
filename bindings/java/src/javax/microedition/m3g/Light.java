package javax.microedition.m3g;

/** JSR-184 1.1 Light over m3g::Light. */
public class Light extends Node {
    public static final int AMBIENT = 128;
    public static final int DIRECTIONAL = 129;
    public static final int OMNI = 130;
    public static final int SPOT = 131;

    public Light() {
        super(create());
    }

    Light(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setMode(int mode);

    public native int getMode();

    public native void setColor(int RGB);

    public native int getColor();

    public native void setIntensity(float intensity);

    public native float getIntensity();

    public native void setSpotAngle(float angle);

    public native float getSpotAngle();

    public native void setSpotExponent(float exponent);

    public native float getSpotExponent();

    public native void setAttenuation(float constant, float linear, float quadratic);

    public native float getConstantAttenuation();

    public native float getLinearAttenuation();

    public native float getQuadraticAttenuation();
}
