package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class Fog extends Object3D {
    Fog(long handle) {
        super(handle);
    }
}
