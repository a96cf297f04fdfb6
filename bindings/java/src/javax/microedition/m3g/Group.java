package javax.microedition.m3g;

/** JSR-184 1.1 Group over m3g::Group. */
public class Group extends Node {
    public Group() {
        super(create());
    }

    Group(long handle) {
        super(handle);
    }

    private static native long create();

    public native void addChild(Node child);

    public native void removeChild(Node child);

    public native int getChildCount();

    public native Node getChild(int index);

    public native boolean pick(int scope, float ox, float oy, float oz, float dx, float dy, float dz,
                               RayIntersection ri);

    public native boolean pick(int scope, float x, float y, Camera camera, RayIntersection ri);
}
