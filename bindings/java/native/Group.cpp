// javax.microedition.m3g.Group's native methods (JSR-184 1.1, Group).
#include <m3g/Camera.h>
#include <m3g/Group.h>
#include <m3g/RayIntersection.h>

#include "Jni.h"
#include "RayIntersections.h"

using namespace m3gjni;
using m3g::Group;

namespace {
// Picks into a fresh result; `ri` (may be null) is written only on a hit.
template <class Pick>
jboolean pickInto(JNIEnv* env, jobject ri, Pick&& pick) {
    return guard(env, [&]() -> jboolean {
        m3g::RayIntersection result;
        const bool hit = pick(ri ? &result : nullptr);
        if (hit && ri) storePick(env, ri, result);
        return static_cast<jboolean>(hit);
    });
}
}  // namespace

M3G_JNI(jlong, Group, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Group>()); });
}

M3G_JNI(void, Group, addChild)(JNIEnv* env, jobject thiz, jobject child) {
    guard(env, [&] { self<Group>(env, thiz)->addChild(arg<m3g::Node>(env, child)); });
}
M3G_JNI(void, Group, removeChild)(JNIEnv* env, jobject thiz, jobject child) {
    guard(env, [&] { self<Group>(env, thiz)->removeChild(arg<m3g::Node>(env, child)); });
}
M3G_JNI(jint, Group, getChildCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Group>(env, thiz)->getChildCount(); });
}
M3G_JNI(jobject, Group, getChild)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<Group>(env, thiz)->getChild(index)); });
}

M3G_JNI(jboolean, Group, pick__IFFFFFFLjavax_microedition_m3g_RayIntersection_2)(
    JNIEnv* env, jobject thiz, jint scope, jfloat ox, jfloat oy, jfloat oz, jfloat dx, jfloat dy, jfloat dz, jobject ri) {
    return pickInto(env, ri, [&](m3g::RayIntersection* result) {
        return self<Group>(env, thiz)->pick(scope, ox, oy, oz, dx, dy, dz, result);
    });
}

M3G_JNI(jboolean, Group, pick__IFFLjavax_microedition_m3g_Camera_2Ljavax_microedition_m3g_RayIntersection_2)(
    JNIEnv* env, jobject thiz, jint scope, jfloat x, jfloat y, jobject camera, jobject ri) {
    return pickInto(env, ri, [&](m3g::RayIntersection* result) {
        return self<Group>(env, thiz)->pick(scope, x, y, arg<m3g::Camera>(env, camera), result);
    });
}
