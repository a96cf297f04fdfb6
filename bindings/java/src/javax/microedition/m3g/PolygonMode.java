package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class PolygonMode extends Object3D {
    PolygonMode(long handle) {
        super(handle);
    }
}
