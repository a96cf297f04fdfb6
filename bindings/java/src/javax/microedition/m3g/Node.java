package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public abstract class Node extends Transformable {
    Node(long handle) {
        super(handle);
    }
}
