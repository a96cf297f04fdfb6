package javax.microedition.m3g;

/** JSR-184 1.1 AnimationController over m3g::AnimationController. */
public class AnimationController extends Object3D {
    public AnimationController() {
        super(create());
    }

    AnimationController(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setActiveInterval(int start, int end);

    public native int getActiveIntervalStart();

    public native int getActiveIntervalEnd();

    public native void setSpeed(float speed, int worldTime);

    public native float getSpeed();

    public native void setPosition(float sequenceTime, int worldTime);

    public native float getPosition(int worldTime);

    public native int getRefWorldTime();

    public native void setWeight(float weight);

    public native float getWeight();
}
