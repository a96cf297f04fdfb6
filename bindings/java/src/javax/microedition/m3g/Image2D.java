package javax.microedition.m3g;

import java.awt.image.BufferedImage;

/**
 * JSR-184 1.1 Image2D over m3g::Image2D. Where JSR-184 takes an lcdui Image
 * ({@link #Image2D(int, Object)}), desktop Java passes a
 * {@link java.awt.image.BufferedImage}.
 */
public class Image2D extends Object3D {
    public static final int ALPHA = 96;
    public static final int LUMINANCE = 97;
    public static final int LUMINANCE_ALPHA = 98;
    public static final int RGB = 99;
    public static final int RGBA = 100;

    /**
     * An immutable image from the pixels of {@code image}, a
     * {@link java.awt.image.BufferedImage} (lcdui's Image in JSR-184),
     * converted to {@code format}. An image without alpha gives ALPHA its
     * luminance.
     *
     * @throws NullPointerException if image is null
     * @throws IllegalArgumentException if image is not a BufferedImage or format is not a valid format
     */
    public Image2D(int format, Object image) {
        super(createFromImage(format, image));
    }

    public Image2D(int format, int width, int height, byte[] image) {
        super(createPixels(format, width, height, image));
    }

    public Image2D(int format, int width, int height, byte[] image, byte[] palette) {
        super(createPalettized(format, width, height, image, palette));
    }

    public Image2D(int format, int width, int height) {
        super(createMutable(format, width, height));
    }

    Image2D(long handle) {
        super(handle);
    }

    /** Reads a BufferedImage's ARGB pixels for the native side (marshalling only). */
    private static long createFromImage(int format, Object image) {
        if (image == null) {
            throw new NullPointerException("Image2D(int, Object): image is null");
        }
        if (!(image instanceof BufferedImage)) {
            throw new IllegalArgumentException("Image2D(int, Object): image is a " + image.getClass().getName()
                    + "; this implementation accepts a java.awt.image.BufferedImage (lcdui's Image in JSR-184)");
        }
        BufferedImage bi = (BufferedImage) image;
        int width = bi.getWidth();
        int height = bi.getHeight();
        int[] argb = bi.getRGB(0, 0, width, height, null, 0, width);
        return createArgb(format, width, height, argb, bi.getColorModel().hasAlpha());
    }

    private static native long createArgb(int format, int width, int height, int[] argb, boolean hasAlpha);

    private static native long createPixels(int format, int width, int height, byte[] image);

    private static native long createPalettized(int format, int width, int height, byte[] image, byte[] palette);

    private static native long createMutable(int format, int width, int height);

    public native void set(int x, int y, int width, int height, byte[] image);

    public native boolean isMutable();

    public native int getFormat();

    public native int getWidth();

    public native int getHeight();

    /** The pixels as stored, palette resolved (tests; JSR-184 has no getter). */
    native byte[] nativePixels();
}
