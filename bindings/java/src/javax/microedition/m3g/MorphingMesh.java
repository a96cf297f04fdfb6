package javax.microedition.m3g;

/** JSR-184 1.1 MorphingMesh over m3g::MorphingMesh. */
public class MorphingMesh extends Mesh {
    public MorphingMesh(VertexBuffer base, VertexBuffer[] targets, IndexBuffer submesh, Appearance appearance) {
        super(create(base, targets, submesh, appearance));
    }

    public MorphingMesh(VertexBuffer base, VertexBuffer[] targets, IndexBuffer[] submeshes,
            Appearance[] appearances) {
        super(createSubmeshes(base, targets, submeshes, appearances));
    }

    MorphingMesh(long handle) {
        super(handle);
    }

    private static native long create(VertexBuffer base, VertexBuffer[] targets, IndexBuffer submesh,
            Appearance appearance);

    private static native long createSubmeshes(VertexBuffer base, VertexBuffer[] targets, IndexBuffer[] submeshes,
            Appearance[] appearances);

    public native VertexBuffer getMorphTarget(int index);

    public native int getMorphTargetCount();

    public native void setWeights(float[] weights);

    public native void getWeights(float[] weights);
}
