// javax.microedition.m3g.Appearance's native methods (JSR-184 1.1, Appearance).
#include <m3g/Appearance.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Material.h>
#include <m3g/PolygonMode.h>
#include <m3g/Texture2D.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Appearance;

M3G_JNI(jlong, Appearance, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Appearance>()); });
}

M3G_JNI(void, Appearance, setLayer)(JNIEnv* env, jobject thiz, jint layer) {
    guard(env, [&] { self<Appearance>(env, thiz)->setLayer(layer); });
}
M3G_JNI(jint, Appearance, getLayer)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Appearance>(env, thiz)->getLayer(); });
}
M3G_JNI(void, Appearance, setCompositingMode)(JNIEnv* env, jobject thiz, jobject mode) {
    guard(env, [&] { self<Appearance>(env, thiz)->setCompositingMode(arg<m3g::CompositingMode>(env, mode)); });
}
M3G_JNI(jobject, Appearance, getCompositingMode)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Appearance>(env, thiz)->getCompositingMode()); });
}
M3G_JNI(void, Appearance, setFog)(JNIEnv* env, jobject thiz, jobject fog) {
    guard(env, [&] { self<Appearance>(env, thiz)->setFog(arg<m3g::Fog>(env, fog)); });
}
M3G_JNI(jobject, Appearance, getFog)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Appearance>(env, thiz)->getFog()); });
}
M3G_JNI(void, Appearance, setPolygonMode)(JNIEnv* env, jobject thiz, jobject mode) {
    guard(env, [&] { self<Appearance>(env, thiz)->setPolygonMode(arg<m3g::PolygonMode>(env, mode)); });
}
M3G_JNI(jobject, Appearance, getPolygonMode)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Appearance>(env, thiz)->getPolygonMode()); });
}
M3G_JNI(void, Appearance, setMaterial)(JNIEnv* env, jobject thiz, jobject material) {
    guard(env, [&] { self<Appearance>(env, thiz)->setMaterial(arg<m3g::Material>(env, material)); });
}
M3G_JNI(jobject, Appearance, getMaterial)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Appearance>(env, thiz)->getMaterial()); });
}
M3G_JNI(void, Appearance, setTexture)(JNIEnv* env, jobject thiz, jint index, jobject texture) {
    guard(env, [&] { self<Appearance>(env, thiz)->setTexture(index, arg<m3g::Texture2D>(env, texture)); });
}
M3G_JNI(jobject, Appearance, getTexture)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<Appearance>(env, thiz)->getTexture(index)); });
}
