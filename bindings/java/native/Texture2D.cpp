// javax.microedition.m3g.Texture2D's native methods (JSR-184 1.1, Texture2D;
// its Transformable methods are Transformable's).
#include <m3g/Image2D.h>
#include <m3g/Texture2D.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Texture2D;

M3G_JNI(jlong, Texture2D, create)(JNIEnv* env, jclass, jobject image) {
    return guard(env, [&] { return handleOf(m3g::make<Texture2D>(arg<m3g::Image2D>(env, image))); });
}

M3G_JNI(void, Texture2D, setImage)(JNIEnv* env, jobject thiz, jobject image) {
    guard(env, [&] { self<Texture2D>(env, thiz)->setImage(arg<m3g::Image2D>(env, image)); });
}
M3G_JNI(jobject, Texture2D, getImage)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Texture2D>(env, thiz)->getImage()); });
}
M3G_JNI(void, Texture2D, setFiltering)(JNIEnv* env, jobject thiz, jint levelFilter, jint imageFilter) {
    guard(env, [&] { self<Texture2D>(env, thiz)->setFiltering(levelFilter, imageFilter); });
}
M3G_JNI(jint, Texture2D, getLevelFilter)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getLevelFilter(); });
}
M3G_JNI(jint, Texture2D, getImageFilter)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getImageFilter(); });
}
M3G_JNI(void, Texture2D, setWrapping)(JNIEnv* env, jobject thiz, jint wrapS, jint wrapT) {
    guard(env, [&] { self<Texture2D>(env, thiz)->setWrapping(wrapS, wrapT); });
}
M3G_JNI(jint, Texture2D, getWrappingS)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getWrappingS(); });
}
M3G_JNI(jint, Texture2D, getWrappingT)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getWrappingT(); });
}
M3G_JNI(void, Texture2D, setBlending)(JNIEnv* env, jobject thiz, jint func) {
    guard(env, [&] { self<Texture2D>(env, thiz)->setBlending(func); });
}
M3G_JNI(jint, Texture2D, getBlending)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getBlending(); });
}
M3G_JNI(void, Texture2D, setBlendColor)(JNIEnv* env, jobject thiz, jint rgb) {
    guard(env, [&] { self<Texture2D>(env, thiz)->setBlendColor(rgb); });
}
M3G_JNI(jint, Texture2D, getBlendColor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Texture2D>(env, thiz)->getBlendColor(); });
}
