// javax.microedition.m3g.PolygonMode's native methods (JSR-184 1.1, PolygonMode).
#include <m3g/PolygonMode.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::PolygonMode;

M3G_JNI(jlong, PolygonMode, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<PolygonMode>()); });
}

M3G_JNI(void, PolygonMode, setCulling)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setCulling(mode); });
}
M3G_JNI(jint, PolygonMode, getCulling)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<PolygonMode>(env, thiz)->getCulling(); });
}
M3G_JNI(void, PolygonMode, setShading)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setShading(mode); });
}
M3G_JNI(jint, PolygonMode, getShading)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<PolygonMode>(env, thiz)->getShading(); });
}
M3G_JNI(void, PolygonMode, setWinding)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setWinding(mode); });
}
M3G_JNI(jint, PolygonMode, getWinding)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<PolygonMode>(env, thiz)->getWinding(); });
}
M3G_JNI(void, PolygonMode, setTwoSidedLightingEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setTwoSidedLightingEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, PolygonMode, isTwoSidedLightingEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<PolygonMode>(env, thiz)->isTwoSidedLightingEnabled()); });
}
M3G_JNI(void, PolygonMode, setLocalCameraLightingEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setLocalCameraLightingEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, PolygonMode, isLocalCameraLightingEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env,
                 [&] { return static_cast<jboolean>(self<PolygonMode>(env, thiz)->isLocalCameraLightingEnabled()); });
}
M3G_JNI(void, PolygonMode, setPerspectiveCorrectionEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<PolygonMode>(env, thiz)->setPerspectiveCorrectionEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, PolygonMode, isPerspectiveCorrectionEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env,
                 [&] { return static_cast<jboolean>(self<PolygonMode>(env, thiz)->isPerspectiveCorrectionEnabled()); });
}
