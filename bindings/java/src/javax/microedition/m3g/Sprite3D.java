package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class Sprite3D extends Node {
    Sprite3D(long handle) {
        super(handle);
    }
}
