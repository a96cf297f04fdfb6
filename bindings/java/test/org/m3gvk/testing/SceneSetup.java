package org.m3gvk.testing;

import javax.microedition.m3g.Background;
import javax.microedition.m3g.Camera;
import javax.microedition.m3g.Group;
import javax.microedition.m3g.Light;
import javax.microedition.m3g.Mesh;
import javax.microedition.m3g.Node;
import javax.microedition.m3g.Object3D;
import javax.microedition.m3g.SkinnedMesh;
import javax.microedition.m3g.Transform;
import javax.microedition.m3g.VertexArray;
import javax.microedition.m3g.VertexBuffer;
import javax.microedition.m3g.World;

/**
 * The scene set-up of the corpus renders (the harness Nokia's reference images
 * were made with, as the m3g tool applies it: tools/m3g/SceneSetup.cpp),
 * written against the public JSR-184 API: the World of the loaded roots (or a
 * new one holding the root nodes), the active camera added to the World when
 * it lies outside, and for a scene without an active camera an auto-framed
 * camera (60 degrees, 20 degrees above, at the bounds' radius) with a light
 * pair and a grey Background where the scene has none.
 */
public final class SceneSetup {
    private SceneSetup() {}

    public static World prepare(Object3D[] roots, int width, int height) {
        World world = null;
        for (Object3D o : roots)
            if (o instanceof World) {
                world = (World) o;
                break;
            }
        if (world == null) {
            world = new World();
            for (Object3D o : roots)
                if (o instanceof Node && ((Node) o).getParent() == null) world.addChild((Node) o);
        }
        Camera active = world.getActiveCamera();
        if (active != null && root(active) != world && active.getParent() == null) world.addChild(active);
        if (active == null) autoFrame(world, width, height);
        return world;
    }

    private static Node root(Node n) {
        while (n.getParent() != null) n = n.getParent();
        return n;
    }

    private static boolean enabledPath(Node n) {
        for (; n != null; n = n.getParent())
            if (!n.isRenderingEnabled()) return false;
        return true;
    }

    private static void bounds(World world, Node node, float[] lo, float[] hi, boolean[] any) {
        if (node instanceof Mesh && enabledPath(node)) {
            VertexBuffer vb = ((Mesh) node).getVertexBuffer();
            float[] scaleBias = {1, 0, 0, 0};
            VertexArray positions = vb != null ? vb.getPositions(scaleBias) : null;
            Transform toWorld = new Transform();
            if (positions != null && node.getTransformTo(world, toWorld)) {
                int n = positions.getVertexCount(), c = positions.getComponentCount();
                int[] values = new int[n * c];
                if (positions.getComponentType() == 1) {
                    byte[] b = new byte[n * c];
                    positions.get(0, n, b);
                    for (int i = 0; i < b.length; ++i) values[i] = b[i];
                } else {
                    short[] s = new short[n * c];
                    positions.get(0, n, s);
                    for (int i = 0; i < s.length; ++i) values[i] = s[i];
                }
                for (int v = 0; v < n; ++v) {
                    float[] p = {scaleBias[0] * values[v * c] + scaleBias[1], scaleBias[0] * values[v * c + 1] + scaleBias[2],
                        scaleBias[0] * values[v * c + 2] + scaleBias[3], 1f};
                    toWorld.transform(p);
                    for (int k = 0; k < 3; ++k) {
                        float x = p[3] != 0f ? p[k] / p[3] : p[k];
                        lo[k] = Math.min(lo[k], x);
                        hi[k] = Math.max(hi[k], x);
                    }
                    any[0] = true;
                }
            }
        }
        // Group children only: a SkinnedMesh's skeleton is not traversed.
        if (node instanceof Group) {
            Group g = (Group) node;
            for (int i = 0; i < g.getChildCount(); ++i) bounds(world, g.getChild(i), lo, hi, any);
        }
    }

    private static boolean contributes(Node node) {
        if (node instanceof Light) {
            Light l = (Light) node;
            if (enabledPath(l) && (l.getColor() & 0xFFFFFF) != 0 && l.getIntensity() != 0f) return true;
        }
        if (node instanceof Group) {
            Group g = (Group) node;
            for (int i = 0; i < g.getChildCount(); ++i)
                if (contributes(g.getChild(i))) return true;
        }
        if (node instanceof SkinnedMesh && ((SkinnedMesh) node).getSkeleton() != null)
            return contributes(((SkinnedMesh) node).getSkeleton());
        return false;
    }

    private static void autoFrame(World world, int width, int height) {
        float[] lo = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY};
        float[] hi = {Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        boolean[] any = {false};
        bounds(world, world, lo, hi, any);
        float[] center = {0, 0, 0};
        float radius = 1f;
        if (any[0]) {
            double r2 = 0;
            for (int k = 0; k < 3; ++k) {
                center[k] = (lo[k] + hi[k]) * 0.5f;
                r2 += (double) (hi[k] - lo[k]) * (hi[k] - lo[k]);
            }
            radius = (float) (Math.sqrt(r2) * 0.5);
            if (radius == 0f) radius = 1f;
        }
        Camera camera = new Camera();
        float aspect = (float) width / (float) height;
        camera.setPerspective(60f, aspect, 0.1f * radius, 10f * radius);
        double h = width >= height ? Math.toRadians(30) : Math.atan(aspect * Math.tan(Math.toRadians(30)));
        double d = radius / Math.sin(h);
        double a20 = Math.toRadians(20);
        camera.setTranslation(center[0], (float) (center[1] + d * Math.sin(a20)), (float) (center[2] + d * Math.cos(a20)));
        camera.setOrientation(-20f, 1f, 0f, 0f);
        world.addChild(camera);
        world.setActiveCamera(camera);
        if (!contributes(world)) {
            Light sun = new Light();
            sun.setMode(Light.DIRECTIONAL);
            sun.setOrientation(54.7356103f, -1f, -1f, 0f);
            world.addChild(sun);
            Light ambient = new Light();
            ambient.setMode(Light.AMBIENT);
            ambient.setIntensity(0.3f);
            world.addChild(ambient);
        }
        if (world.getBackground() == null) {
            Background bg = new Background();
            bg.setColor(0xFF404040);
            world.setBackground(bg);
        }
    }
}
