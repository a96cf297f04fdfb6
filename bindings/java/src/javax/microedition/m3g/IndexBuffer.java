package javax.microedition.m3g;

/** JSR-184 1.1 IndexBuffer (abstract) over m3g::IndexBuffer; TriangleStripArray is its one subclass. */
public abstract class IndexBuffer extends Object3D {
    IndexBuffer(long handle) {
        super(handle);
    }

    public abstract int getIndexCount();

    public abstract void getIndices(int[] indices);
}
