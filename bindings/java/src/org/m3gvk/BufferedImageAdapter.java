package org.m3gvk;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.SinglePixelPackedSampleModel;
import java.awt.image.WritableRaster;

/**
 * BufferedImage as a Graphics3D target, no clip or translation. INT_ARGB and
 * INT_RGB images whose raster is the whole int array are copied directly
 * (INT_RGB reads as opaque); any other type goes through getRGB/setRGB
 * (ARGB; an image without alpha keeps its own).
 */
final class BufferedImageAdapter implements TargetAdapter {
    @Override
    public int getWidth(Object target) {
        return ((BufferedImage) target).getWidth();
    }

    @Override
    public int getHeight(Object target) {
        return ((BufferedImage) target).getHeight();
    }

    /** The image's pixels as one int array, rows of width, or null when it is not laid out so. */
    private static int[] packed(BufferedImage image) {
        int type = image.getType();
        if (type != BufferedImage.TYPE_INT_ARGB && type != BufferedImage.TYPE_INT_RGB) return null;
        WritableRaster raster = image.getRaster();
        if (!(raster.getDataBuffer() instanceof DataBufferInt) || raster.getParent() != null
            || raster.getSampleModelTranslateX() != 0 || raster.getSampleModelTranslateY() != 0
            || !(raster.getSampleModel() instanceof SinglePixelPackedSampleModel)
            || ((SinglePixelPackedSampleModel) raster.getSampleModel()).getScanlineStride() != image.getWidth())
            return null;
        DataBufferInt buffer = (DataBufferInt) raster.getDataBuffer();
        if (buffer.getNumBanks() != 1 || buffer.getOffset() != 0) return null;
        int[] data = buffer.getData();
        return data.length >= image.getWidth() * image.getHeight() ? data : null;
    }

    @Override
    public void readPixels(Object target, int[] argb) {
        BufferedImage image = (BufferedImage) target;
        int[] data = packed(image);
        if (data == null) {
            image.getRGB(0, 0, image.getWidth(), image.getHeight(), argb, 0, image.getWidth());
            return;
        }
        System.arraycopy(data, 0, argb, 0, argb.length);
        if (image.getType() == BufferedImage.TYPE_INT_RGB)
            for (int i = 0; i < argb.length; ++i) argb[i] |= 0xFF000000;
    }

    @Override
    public void writePixels(Object target, int[] argb) {
        BufferedImage image = (BufferedImage) target;
        int[] data = packed(image);
        if (data == null) {
            image.setRGB(0, 0, image.getWidth(), image.getHeight(), argb, 0, image.getWidth());
            return;
        }
        System.arraycopy(argb, 0, data, 0, argb.length);
    }
}
