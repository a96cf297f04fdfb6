package javax.microedition.m3g;

import java.util.Hashtable;
import org.m3gvk.TargetAdapter;
import org.m3gvk.TargetAdapters;

/**
 * JSR-184 1.1 Graphics3D over m3g::Graphics3D: one per thread, as m3g-vk
 * has (docs/threading.md). A target is an Image2D, a BufferedImage or an
 * object whose class has an {@link org.m3gvk.TargetAdapter}; for the latter
 * two the pixels travel through a native Graphics at bindTarget and back at
 * releaseTarget.
 */
public class Graphics3D {
    public static final int ANTIALIAS = 2;
    public static final int DITHER = 4;
    public static final int TRUE_COLOR = 8;
    public static final int OVERWRITE = 16;

    static {
        Native.ensureLoaded();
    }

    private static final ThreadLocal<Graphics3D> INSTANCES = ThreadLocal.withInitial(Graphics3D::new);

    /** The native Graphics3D: the process-wide one for the first thread, one of its own for each other. */
    private final long handle;
    /** Where adapter targets are drawn: a native Graphics and its pixels, made at first use. */
    private static final class Surface {
        long handle;
        int width, height;
        int[] pixels;
    }

    private final Surface surface = new Surface();
    private Object target;
    private TargetAdapter adapter;

    private Graphics3D() {
        long[] made = new long[2];
        acquire(made);
        handle = made[0];
        Native.CLEANER.register(this, new Release(made[0], made[1] != 0, surface));
    }

    /** Frees the surface, and a thread's own native Graphics3D (never the process-wide one). */
    private static final class Release implements Runnable {
        private final long handle;
        private final boolean owned;
        private final Surface surface;

        Release(long handle, boolean owned, Surface surface) {
            this.handle = handle;
            this.owned = owned;
            this.surface = surface;
        }

        @Override
        public void run() {
            if (surface.handle != 0) destroySurface(surface.handle);
            if (owned) destroy(handle);
        }
    }

    public static Graphics3D getInstance() {
        return INSTANCES.get();
    }

    public static Hashtable<String, Object> getProperties() {
        Hashtable<String, Object> table = new Hashtable<>();
        fillProperties(table);
        return table;
    }

    public void bindTarget(Object target) {
        bindTarget(target, true, 0);
    }

    public void bindTarget(Object target, boolean depthBuffer, int hints) {
        if (target == null) throw new NullPointerException("Graphics3D.bindTarget: the target is null");
        if (this.target != null)
            throw new IllegalStateException("Graphics3D.bindTarget: a target is already bound (releaseTarget first)");
        if (target instanceof Image2D) {
            bindImage(handle, (Image2D) target, depthBuffer, hints);
            this.target = target;
            return;
        }
        TargetAdapter a = TargetAdapters.find(target);
        if (a == null)
            throw new IllegalArgumentException("Graphics3D.bindTarget: " + target.getClass().getName()
                + " is not a target: an Image2D, a java.awt.image.BufferedImage, or a class with an"
                + " org.m3gvk.TargetAdapter registered");
        int w = a.getWidth(target), h = a.getHeight(target);
        if (w <= 0 || h <= 0)
            throw new IllegalArgumentException("Graphics3D.bindTarget: the target is " + w + "x" + h + " pixels");
        Surface s = surface;
        if (s.handle == 0 || w != s.width || h != s.height) {
            if (s.handle != 0) destroySurface(s.handle);
            s.handle = 0;
            s.handle = createSurface(w, h);
            s.width = w;
            s.height = h;
            s.pixels = new int[w * h];
        }
        a.readPixels(target, s.pixels);
        int[] clip = a.getClip(target);
        bindSurface(handle, s.handle, s.pixels, a.getTranslateX(target), a.getTranslateY(target), clip[0], clip[1], clip[2],
            clip[3], depthBuffer, hints);
        this.target = target;
        this.adapter = a;
    }

    public void releaseTarget() {
        if (target == null) return;
        Object t = target;
        TargetAdapter a = adapter;
        target = null;
        adapter = null;
        if (a == null) {
            release(handle, 0, null);
            return;
        }
        release(handle, surface.handle, surface.pixels);
        a.writePixels(t, surface.pixels);
    }

    public Object getTarget() {
        return target;
    }

    public int getHints() {
        return getHints(handle);
    }

    public boolean isDepthBufferEnabled() {
        return isDepthBufferEnabled(handle);
    }

    public void setViewport(int x, int y, int width, int height) {
        setViewport(handle, x, y, width, height);
    }

    public int getViewportX() {
        return viewport(handle, 0);
    }

    public int getViewportY() {
        return viewport(handle, 1);
    }

    public int getViewportWidth() {
        return viewport(handle, 2);
    }

    public int getViewportHeight() {
        return viewport(handle, 3);
    }

    public void setDepthRange(float near, float far) {
        setDepthRange(handle, near, far);
    }

    public float getDepthRangeNear() {
        return depthRange(handle, false);
    }

    public float getDepthRangeFar() {
        return depthRange(handle, true);
    }

    public void clear(Background background) {
        clear(handle, background);
    }

    public void render(World world) {
        renderWorld(handle, world);
    }

    public void render(Node node, Transform transform) {
        renderNode(handle, node, transform);
    }

    public void render(VertexBuffer vertices, IndexBuffer triangles, Appearance appearance, Transform transform) {
        renderImmediate(handle, vertices, triangles, appearance, transform, -1);
    }

    public void render(VertexBuffer vertices, IndexBuffer triangles, Appearance appearance, Transform transform,
            int scope) {
        renderImmediate(handle, vertices, triangles, appearance, transform, scope);
    }

    public void setCamera(Camera camera, Transform transform) {
        setCamera(handle, camera, transform);
    }

    public Camera getCamera(Transform transform) {
        return getCamera(handle, transform);
    }

    public int addLight(Light light, Transform transform) {
        return addLight(handle, light, transform);
    }

    public void setLight(int index, Light light, Transform transform) {
        setLight(handle, index, light, transform);
    }

    public void resetLights() {
        resetLights(handle);
    }

    public int getLightCount() {
        return getLightCount(handle);
    }

    public Light getLight(int index, Transform transform) {
        return getLight(handle, index, transform);
    }

    // ---- native (m3g::Graphics3D); `g` is the handle ----
    private static native void acquire(long[] made);

    private static native void destroy(long g);

    private static native long createSurface(int width, int height);

    private static native void destroySurface(long surface);

    private static native void fillProperties(Hashtable<String, Object> table);

    private static native void bindImage(long g, Image2D image, boolean depth, int hints);

    private static native void bindSurface(long g, long surface, int[] pixels, int translateX, int translateY, int clipX,
            int clipY, int clipWidth, int clipHeight, boolean depth, int hints);

    private static native void release(long g, long surface, int[] pixels);

    private static native int getHints(long g);

    private static native boolean isDepthBufferEnabled(long g);

    private static native void setViewport(long g, int x, int y, int width, int height);

    private static native int viewport(long g, int which);

    private static native void setDepthRange(long g, float near, float far);

    private static native float depthRange(long g, boolean far);

    private static native void clear(long g, Background background);

    private static native void renderWorld(long g, World world);

    private static native void renderNode(long g, Node node, Transform transform);

    private static native void renderImmediate(long g, VertexBuffer vertices, IndexBuffer triangles,
            Appearance appearance, Transform transform, int scope);

    private static native void setCamera(long g, Camera camera, Transform transform);

    private static native Camera getCamera(long g, Transform transform);

    private static native int addLight(long g, Light light, Transform transform);

    private static native void setLight(long g, int index, Light light, Transform transform);

    private static native void resetLights(long g);

    private static native int getLightCount(long g);

    private static native Light getLight(long g, int index, Transform transform);
}
