package javax.microedition.m3g;

/** PLACEHOLDER (bindings/java work in progress): the class's members are not written yet. */
public class AnimationTrack extends Object3D {
    AnimationTrack(long handle) {
        super(handle);
    }
}
