package javax.microedition.m3g;

/** JSR-184 1.1 Mesh over m3g::Mesh. */
public class Mesh extends Node {
    public Mesh(VertexBuffer vertices, IndexBuffer submesh, Appearance appearance) {
        super(create(vertices, submesh, appearance));
    }

    public Mesh(VertexBuffer vertices, IndexBuffer[] submeshes, Appearance[] appearances) {
        super(createSubmeshes(vertices, submeshes, appearances));
    }

    Mesh(long handle) {
        super(handle);
    }

    private static native long create(VertexBuffer vertices, IndexBuffer submesh, Appearance appearance);

    private static native long createSubmeshes(VertexBuffer vertices, IndexBuffer[] submeshes,
            Appearance[] appearances);

    public native void setAppearance(int index, Appearance appearance);

    public native Appearance getAppearance(int index);

    public native IndexBuffer getIndexBuffer(int index);

    public native VertexBuffer getVertexBuffer();

    public native int getSubmeshCount();
}
