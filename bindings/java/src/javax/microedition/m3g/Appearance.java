package javax.microedition.m3g;

/** JSR-184 1.1 Appearance over m3g::Appearance. */
public class Appearance extends Object3D {
    public Appearance() {
        super(create());
    }

    Appearance(long handle) {
        super(handle);
    }

    private static native long create();

    public native void setLayer(int layer);

    public native int getLayer();

    public native void setFog(Fog fog);

    public native Fog getFog();

    public native void setPolygonMode(PolygonMode polygonMode);

    public native PolygonMode getPolygonMode();

    public native void setCompositingMode(CompositingMode compositingMode);

    public native CompositingMode getCompositingMode();

    public native void setTexture(int index, Texture2D texture);

    public native Texture2D getTexture(int index);

    public native void setMaterial(Material material);

    public native Material getMaterial();
}
