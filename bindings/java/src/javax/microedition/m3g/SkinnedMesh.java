package javax.microedition.m3g;

/** JSR-184 1.1 SkinnedMesh over m3g::SkinnedMesh. */
public class SkinnedMesh extends Mesh {
    public SkinnedMesh(VertexBuffer vertices, IndexBuffer submesh, Appearance appearance, Group skeleton) {
        super(create(vertices, submesh, appearance, skeleton));
    }

    public SkinnedMesh(VertexBuffer vertices, IndexBuffer[] submeshes, Appearance[] appearances, Group skeleton) {
        super(createSubmeshes(vertices, submeshes, appearances, skeleton));
    }

    SkinnedMesh(long handle) {
        super(handle);
    }

    private static native long create(VertexBuffer vertices, IndexBuffer submesh, Appearance appearance,
            Group skeleton);

    private static native long createSubmeshes(VertexBuffer vertices, IndexBuffer[] submeshes,
            Appearance[] appearances, Group skeleton);

    public native void addTransform(Node bone, int weight, int firstVertex, int numVertices);

    public native Group getSkeleton();

    public native void getBoneTransform(Node bone, Transform transform);

    public native int getBoneVertices(Node bone, int[] indices, float[] weights);
}
