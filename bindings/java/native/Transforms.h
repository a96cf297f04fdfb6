// javax.microedition.m3g.Transform as m3g::Transform: its float[16] field
// (row-major, as m3g::Transform::get/set) read and written.
#pragma once

#include <jni.h>

#include <m3g/Transform.h>

namespace m3gjni {

/// The matrix of a Java Transform; NullPointerException naming `where` for null.
m3g::Transform transformOf(JNIEnv* env, jobject transform, const char* where);
/// The matrix of a Java Transform, or nullopt-like false for null.
bool transformOf(JNIEnv* env, jobject transform, m3g::Transform& out);
/// Writes `value` into a Java Transform (non-null).
void store(JNIEnv* env, jobject transform, const m3g::Transform& value);

}  // namespace m3gjni
