package javax.microedition.m3g;

/** JSR-184 1.1 Node over m3g::Node. */
public abstract class Node extends Transformable {
    public static final int NONE = 144;
    public static final int ORIGIN = 145;
    public static final int X_AXIS = 146;
    public static final int Y_AXIS = 147;
    public static final int Z_AXIS = 148;

    Node(long handle) {
        super(handle);
    }

    public native Node getParent();

    public native boolean getTransformTo(Node target, Transform transform);

    public native void setAlignment(Node zRef, int zTarget, Node yRef, int yTarget);

    public final native void align(Node reference);

    public native Node getAlignmentReference(int axis);

    public native int getAlignmentTarget(int axis);

    public native void setAlphaFactor(float alphaFactor);

    public native float getAlphaFactor();

    public native void setRenderingEnable(boolean enable);

    public native boolean isRenderingEnabled();

    public native void setPickingEnable(boolean enable);

    public native boolean isPickingEnabled();

    public native void setScope(int scope);

    public native int getScope();
}
