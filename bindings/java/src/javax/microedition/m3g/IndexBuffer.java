package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public abstract class IndexBuffer extends Object3D {
    IndexBuffer(long handle) {
        super(handle);
    }
}
