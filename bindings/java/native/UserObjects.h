// Object3D.userObject (JSR-184 1.1): any Java object, kept with the native
// object so that it survives its peer (a node reached again through
// getChild after its first peer was collected still has it), copied by
// duplicate(), and collected when nothing but a cycle through it remains
// (docs/java.md, "Identity and lifetime").
//
// The native object holds the user object in a UserObject (its std::any user
// object): a strong JNI reference while anything but the peer holds the
// native object (a parent, an Appearance's owner, Graphics3D...), a weak one
// while only the peer does; the peer then holds it too (its userObjectHold
// field), so a cycle from the user object back to the peer is garbage. The
// hold is rechecked after every call that passed the object (the only way
// something new can come to hold it) and after references are dropped.
#pragma once

#include <jni.h>

#include <m3g/Object3D.h>

namespace m3gjni {

/// Sets `object`'s user object (null clears it).
void setUserObject(JNIEnv* env, m3g::Object3D* object, jobject value);
/// `object`'s user object as a local reference, or null. A file's user
/// parameters (the Loader's) become a java.util.Hashtable<Integer, byte[]>
/// the first time, as JSR-184 1.1's Loader specifies, and stay that object.
jobject userObject(JNIEnv* env, m3g::Object3D* object);
/// Gives the copies of a duplicate() their own hold of the user objects
/// they share with the originals.
void adoptDuplicates(JNIEnv* env, m3g::Object3D* copyRoot);
void recheckUserObject(JNIEnv* env, m3g::Object3D* object) noexcept;
void recheckAllUserObjects(JNIEnv* env) noexcept;

}  // namespace m3gjni
