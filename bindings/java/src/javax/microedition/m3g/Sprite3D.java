package javax.microedition.m3g;

/** JSR-184 1.1 Sprite3D over m3g::Sprite3D. */
public class Sprite3D extends Node {
    public Sprite3D(boolean scaled, Image2D image, Appearance appearance) {
        super(create(scaled, image, appearance));
    }

    Sprite3D(long handle) {
        super(handle);
    }

    private static native long create(boolean scaled, Image2D image, Appearance appearance);

    public native boolean isScaled();

    public native void setAppearance(Appearance appearance);

    public native Appearance getAppearance();

    public native void setImage(Image2D image);

    public native Image2D getImage();

    public native void setCrop(int cropX, int cropY, int width, int height);

    public native int getCropX();

    public native int getCropY();

    public native int getCropWidth();

    public native int getCropHeight();
}
