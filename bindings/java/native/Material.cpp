// javax.microedition.m3g.Material's native methods (JSR-184 1.1, Material).
#include <m3g/Material.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Material;

M3G_JNI(jlong, Material, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Material>()); });
}

M3G_JNI(void, Material, setColor)(JNIEnv* env, jobject thiz, jint target, jint argb) {
    guard(env, [&] { self<Material>(env, thiz)->setColor(target, argb); });
}
M3G_JNI(jint, Material, getColor)(JNIEnv* env, jobject thiz, jint target) {
    return guard(env, [&] { return self<Material>(env, thiz)->getColor(target); });
}
M3G_JNI(void, Material, setShininess)(JNIEnv* env, jobject thiz, jfloat shininess) {
    guard(env, [&] { self<Material>(env, thiz)->setShininess(shininess); });
}
M3G_JNI(jfloat, Material, getShininess)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Material>(env, thiz)->getShininess(); });
}
M3G_JNI(void, Material, setVertexColorTrackingEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<Material>(env, thiz)->setVertexColorTrackingEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, Material, isVertexColorTrackingEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Material>(env, thiz)->isVertexColorTrackingEnabled()); });
}
