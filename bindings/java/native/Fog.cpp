// javax.microedition.m3g.Fog's native methods (JSR-184 1.1, Fog).
#include <m3g/Fog.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Fog;

M3G_JNI(jlong, Fog, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Fog>()); });
}

M3G_JNI(void, Fog, setMode)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<Fog>(env, thiz)->setMode(mode); });
}
M3G_JNI(jint, Fog, getMode)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Fog>(env, thiz)->getMode(); });
}
M3G_JNI(void, Fog, setLinear)(JNIEnv* env, jobject thiz, jfloat nearDistance, jfloat farDistance) {
    guard(env, [&] { self<Fog>(env, thiz)->setLinear(nearDistance, farDistance); });
}
M3G_JNI(jfloat, Fog, getNearDistance)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Fog>(env, thiz)->getNearDistance(); });
}
M3G_JNI(jfloat, Fog, getFarDistance)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Fog>(env, thiz)->getFarDistance(); });
}
M3G_JNI(void, Fog, setDensity)(JNIEnv* env, jobject thiz, jfloat density) {
    guard(env, [&] { self<Fog>(env, thiz)->setDensity(density); });
}
M3G_JNI(jfloat, Fog, getDensity)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Fog>(env, thiz)->getDensity(); });
}
M3G_JNI(void, Fog, setColor)(JNIEnv* env, jobject thiz, jint rgb) {
    guard(env, [&] { self<Fog>(env, thiz)->setColor(rgb); });
}
M3G_JNI(jint, Fog, getColor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Fog>(env, thiz)->getColor(); });
}
