// javax.microedition.m3g.CompositingMode's native methods (JSR-184 1.1, CompositingMode).
#include <m3g/CompositingMode.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::CompositingMode;

M3G_JNI(jlong, CompositingMode, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<CompositingMode>()); });
}

M3G_JNI(void, CompositingMode, setBlending)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setBlending(mode); });
}
M3G_JNI(jint, CompositingMode, getBlending)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<CompositingMode>(env, thiz)->getBlending(); });
}
M3G_JNI(void, CompositingMode, setAlphaThreshold)(JNIEnv* env, jobject thiz, jfloat threshold) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setAlphaThreshold(threshold); });
}
M3G_JNI(jfloat, CompositingMode, getAlphaThreshold)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<CompositingMode>(env, thiz)->getAlphaThreshold(); });
}
M3G_JNI(void, CompositingMode, setDepthTestEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setDepthTestEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, CompositingMode, isDepthTestEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<CompositingMode>(env, thiz)->isDepthTestEnabled()); });
}
M3G_JNI(void, CompositingMode, setDepthWriteEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setDepthWriteEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, CompositingMode, isDepthWriteEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<CompositingMode>(env, thiz)->isDepthWriteEnabled()); });
}
M3G_JNI(void, CompositingMode, setColorWriteEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setColorWriteEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, CompositingMode, isColorWriteEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<CompositingMode>(env, thiz)->isColorWriteEnabled()); });
}
M3G_JNI(void, CompositingMode, setAlphaWriteEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setAlphaWriteEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, CompositingMode, isAlphaWriteEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<CompositingMode>(env, thiz)->isAlphaWriteEnabled()); });
}
M3G_JNI(void, CompositingMode, setDepthOffset)(JNIEnv* env, jobject thiz, jfloat factor, jfloat units) {
    guard(env, [&] { self<CompositingMode>(env, thiz)->setDepthOffset(factor, units); });
}
M3G_JNI(jfloat, CompositingMode, getDepthOffsetFactor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<CompositingMode>(env, thiz)->getDepthOffsetFactor(); });
}
M3G_JNI(jfloat, CompositingMode, getDepthOffsetUnits)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<CompositingMode>(env, thiz)->getDepthOffsetUnits(); });
}
