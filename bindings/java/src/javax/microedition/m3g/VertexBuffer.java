package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class VertexBuffer extends Object3D {
    VertexBuffer(long handle) {
        super(handle);
    }
}
