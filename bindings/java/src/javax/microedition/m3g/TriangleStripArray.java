package javax.microedition.m3g;

/** JSR-184 1.1 TriangleStripArray over m3g::TriangleStripArray. */
public class TriangleStripArray extends IndexBuffer {
    public TriangleStripArray(int firstIndex, int[] stripLengths) {
        super(createImplicit(firstIndex, stripLengths));
    }

    public TriangleStripArray(int[] indices, int[] stripLengths) {
        super(createExplicit(indices, stripLengths));
    }

    TriangleStripArray(long handle) {
        super(handle);
    }

    private static native long createImplicit(int firstIndex, int[] stripLengths);

    private static native long createExplicit(int[] indices, int[] stripLengths);

    @Override
    public native int getIndexCount();

    @Override
    public native void getIndices(int[] indices);
}
