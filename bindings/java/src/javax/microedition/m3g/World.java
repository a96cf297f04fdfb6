package javax.microedition.m3g;

/** JSR-184 1.1 World over m3g::World. */
public class World extends Group {
    public World() {
        super(create());
    }

    World(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setActiveCamera(Camera camera);

    public native Camera getActiveCamera();

    public native void setBackground(Background background);

    public native Background getBackground();
}
