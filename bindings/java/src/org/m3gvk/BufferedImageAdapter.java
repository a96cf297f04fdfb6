package org.m3gvk;

import java.awt.image.BufferedImage;

/**
 * BufferedImage as a Graphics3D target: any type, through getRGB/setRGB
 * (ARGB; an image without alpha keeps its own), no clip or translation.
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

    @Override
    public void readPixels(Object target, int[] argb) {
        BufferedImage image = (BufferedImage) target;
        image.getRGB(0, 0, image.getWidth(), image.getHeight(), argb, 0, image.getWidth());
    }

    @Override
    public void writePixels(Object target, int[] argb) {
        BufferedImage image = (BufferedImage) target;
        image.setRGB(0, 0, image.getWidth(), image.getHeight(), argb, 0, image.getWidth());
    }
}
