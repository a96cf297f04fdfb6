// javax.microedition.m3g.Light's native methods (JSR-184 1.1, Light).
#include <m3g/Light.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Light;

M3G_JNI(jlong, Light, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Light>()); });
}

M3G_JNI(void, Light, setMode)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<Light>(env, thiz)->setMode(mode); });
}
M3G_JNI(jint, Light, getMode)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getMode(); });
}
M3G_JNI(void, Light, setColor)(JNIEnv* env, jobject thiz, jint rgb) {
    guard(env, [&] { self<Light>(env, thiz)->setColor(rgb); });
}
M3G_JNI(jint, Light, getColor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getColor(); });
}
M3G_JNI(void, Light, setIntensity)(JNIEnv* env, jobject thiz, jfloat intensity) {
    guard(env, [&] { self<Light>(env, thiz)->setIntensity(intensity); });
}
M3G_JNI(jfloat, Light, getIntensity)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getIntensity(); });
}
M3G_JNI(void, Light, setSpotAngle)(JNIEnv* env, jobject thiz, jfloat angle) {
    guard(env, [&] { self<Light>(env, thiz)->setSpotAngle(angle); });
}
M3G_JNI(jfloat, Light, getSpotAngle)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getSpotAngle(); });
}
M3G_JNI(void, Light, setSpotExponent)(JNIEnv* env, jobject thiz, jfloat exponent) {
    guard(env, [&] { self<Light>(env, thiz)->setSpotExponent(exponent); });
}
M3G_JNI(jfloat, Light, getSpotExponent)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getSpotExponent(); });
}
M3G_JNI(void, Light, setAttenuation)(JNIEnv* env, jobject thiz, jfloat constant, jfloat linear, jfloat quadratic) {
    guard(env, [&] { self<Light>(env, thiz)->setAttenuation(constant, linear, quadratic); });
}
M3G_JNI(jfloat, Light, getConstantAttenuation)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getConstantAttenuation(); });
}
M3G_JNI(jfloat, Light, getLinearAttenuation)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getLinearAttenuation(); });
}
M3G_JNI(jfloat, Light, getQuadraticAttenuation)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Light>(env, thiz)->getQuadraticAttenuation(); });
}
