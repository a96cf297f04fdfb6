package org.m3gvk;

/**
 * How Graphics3D.bindTarget draws into a kind of object it does not know: an
 * emulator's javax.microedition.lcdui.Graphics, a canvas, a frame buffer
 * (docs/java.md, "Rendering into an emulator's Graphics"). Register one with
 * {@link TargetAdapters#register}; java.awt.image.BufferedImage has one built
 * in.
 *
 * <p>At bindTarget the adapter describes the target (size, clip, translation,
 * as lcdui's Graphics has them) and hands over its current pixels; the frame
 * is drawn over them, inside the clip; at releaseTarget the adapter receives
 * the pixels back. Pixels are 0xAARRGGBB ints, rows top to bottom,
 * width * height of them. Called on the thread that calls Graphics3D.
 */
public interface TargetAdapter {
    /** The surface's width in pixels (positive). */
    int getWidth(Object target);

    /** The surface's height in pixels (positive). */
    int getHeight(Object target);

    /** The origin's translation, as lcdui's Graphics.getTranslateX(); 0 by default. */
    default int getTranslateX(Object target) {
        return 0;
    }

    default int getTranslateY(Object target) {
        return 0;
    }

    /**
     * The clip rectangle in translated coordinates: {x, y, width, height}, as
     * lcdui's getClipX/Y/Width/Height; the whole surface by default.
     */
    default int[] getClip(Object target) {
        return new int[] {-getTranslateX(target), -getTranslateY(target), getWidth(target), getHeight(target)};
    }

    /** Copies the surface's pixels into {@code argb} (width * height ints). */
    void readPixels(Object target, int[] argb);

    /** Copies the rendered frame (width * height ints) into the surface. */
    void writePixels(Object target, int[] argb);
}
