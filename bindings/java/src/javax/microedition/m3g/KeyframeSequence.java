package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class KeyframeSequence extends Object3D {
    KeyframeSequence(long handle) {
        super(handle);
    }
}
