package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class Image2D extends Object3D {
    Image2D(long handle) {
        super(handle);
    }
}
