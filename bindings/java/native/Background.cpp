// javax.microedition.m3g.Background's native methods (JSR-184 1.1, Background).
#include <m3g/Background.h>
#include <m3g/Image2D.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Background;

M3G_JNI(jlong, Background, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Background>()); });
}

M3G_JNI(void, Background, setColor)(JNIEnv* env, jobject thiz, jint argb) {
    guard(env, [&] { self<Background>(env, thiz)->setColor(argb); });
}
M3G_JNI(jint, Background, getColor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getColor(); });
}
M3G_JNI(void, Background, setImage)(JNIEnv* env, jobject thiz, jobject image) {
    guard(env, [&] { self<Background>(env, thiz)->setImage(arg<m3g::Image2D>(env, image)); });
}
M3G_JNI(jobject, Background, getImage)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Background>(env, thiz)->getImage()); });
}
M3G_JNI(void, Background, setImageMode)(JNIEnv* env, jobject thiz, jint x, jint y) {
    guard(env, [&] { self<Background>(env, thiz)->setImageMode(x, y); });
}
M3G_JNI(jint, Background, getImageModeX)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getImageModeX(); });
}
M3G_JNI(jint, Background, getImageModeY)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getImageModeY(); });
}
M3G_JNI(void, Background, setCrop)(JNIEnv* env, jobject thiz, jint x, jint y, jint w, jint h) {
    guard(env, [&] { self<Background>(env, thiz)->setCrop(x, y, w, h); });
}
M3G_JNI(jint, Background, getCropX)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getCropX(); });
}
M3G_JNI(jint, Background, getCropY)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getCropY(); });
}
M3G_JNI(jint, Background, getCropWidth)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getCropWidth(); });
}
M3G_JNI(jint, Background, getCropHeight)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Background>(env, thiz)->getCropHeight(); });
}
M3G_JNI(void, Background, setColorClearEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<Background>(env, thiz)->setColorClearEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, Background, isColorClearEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Background>(env, thiz)->isColorClearEnabled()); });
}
M3G_JNI(void, Background, setDepthClearEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<Background>(env, thiz)->setDepthClearEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, Background, isDepthClearEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Background>(env, thiz)->isDepthClearEnabled()); });
}
