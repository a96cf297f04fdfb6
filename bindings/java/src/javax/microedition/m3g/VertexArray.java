package javax.microedition.m3g;

/** JSR-184 1.1 VertexArray over m3g::VertexArray. */
public class VertexArray extends Object3D {
    public VertexArray(int numVertices, int numComponents, int componentSize) {
        super(create(numVertices, numComponents, componentSize));
    }

    VertexArray(long handle) {
        super(handle);
    }

    private static native long create(int numVertices, int numComponents, int componentSize);

    public void set(int firstVertex, int numVertices, short[] values) {
        setShorts(firstVertex, numVertices, values);
    }

    public void set(int firstVertex, int numVertices, byte[] values) {
        setBytes(firstVertex, numVertices, values);
    }

    public void get(int firstVertex, int numVertices, short[] values) {
        getShorts(firstVertex, numVertices, values);
    }

    public void get(int firstVertex, int numVertices, byte[] values) {
        getBytes(firstVertex, numVertices, values);
    }

    private native void setShorts(int firstVertex, int numVertices, short[] values);

    private native void setBytes(int firstVertex, int numVertices, byte[] values);

    private native void getShorts(int firstVertex, int numVertices, short[] values);

    private native void getBytes(int firstVertex, int numVertices, byte[] values);

    public native int getComponentCount();

    public native int getComponentType();

    public native int getVertexCount();
}
