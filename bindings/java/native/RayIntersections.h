// The native result behind a Java RayIntersection, shared by
// RayIntersection.cpp (its getters) and Group.cpp (pick).
#pragma once

#include <jni.h>

#include <m3g/RayIntersection.h>

namespace m3gjni {

/// The native result behind a Java RayIntersection (its `handle` field). It
/// never holds the intersected node; the Java object does (its `intersected`
/// field), so the native result can be freed on the Cleaner's thread.
m3g::RayIntersection* rayIntersectionOf(JNIEnv* env, jobject ri);
/// Stores a pick's result in a Java RayIntersection: the intersected node
/// as its peer, the rest natively.
void storePick(JNIEnv* env, jobject ri, const m3g::RayIntersection& result);

}  // namespace m3gjni
