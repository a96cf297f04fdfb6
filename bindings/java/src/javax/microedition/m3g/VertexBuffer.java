package javax.microedition.m3g;

/** JSR-184 1.1 VertexBuffer over m3g::VertexBuffer. */
public class VertexBuffer extends Object3D {
    public VertexBuffer() {
        super(create());
    }

    VertexBuffer(long handle) {
        super(handle);
    }

    private static native long create();

    public native int getVertexCount();

    public native void setPositions(VertexArray positions, float scale, float[] bias);

    public native void setTexCoords(int index, VertexArray texCoords, float scale, float[] bias);

    public native void setNormals(VertexArray normals);

    public native void setColors(VertexArray colors);

    public native VertexArray getPositions(float[] scaleBias);

    public native VertexArray getTexCoords(int index, float[] scaleBias);

    public native VertexArray getNormals();

    public native VertexArray getColors();

    public native void setDefaultColor(int ARGB);

    public native int getDefaultColor();
}
