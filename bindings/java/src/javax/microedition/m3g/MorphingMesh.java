package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class MorphingMesh extends Mesh {
    MorphingMesh(long handle) {
        super(handle);
    }
}
