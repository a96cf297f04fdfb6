package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class Light extends Node {
    Light(long handle) {
        super(handle);
    }
}
