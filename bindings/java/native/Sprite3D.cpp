// javax.microedition.m3g.Sprite3D's native methods (JSR-184 1.1, Sprite3D).
#include <m3g/Appearance.h>
#include <m3g/Image2D.h>
#include <m3g/Sprite3D.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::Sprite3D;

M3G_JNI(jlong, Sprite3D, create)(JNIEnv* env, jclass, jboolean scaled, jobject image, jobject appearance) {
    return guard(env, [&] {
        return handleOf(
            m3g::make<Sprite3D>(scaled == JNI_TRUE, arg<m3g::Image2D>(env, image), arg<m3g::Appearance>(env, appearance)));
    });
}

M3G_JNI(jboolean, Sprite3D, isScaled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Sprite3D>(env, thiz)->isScaled()); });
}
M3G_JNI(void, Sprite3D, setAppearance)(JNIEnv* env, jobject thiz, jobject appearance) {
    guard(env, [&] { self<Sprite3D>(env, thiz)->setAppearance(arg<m3g::Appearance>(env, appearance)); });
}
M3G_JNI(jobject, Sprite3D, getAppearance)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Sprite3D>(env, thiz)->getAppearance()); });
}
M3G_JNI(void, Sprite3D, setImage)(JNIEnv* env, jobject thiz, jobject image) {
    guard(env, [&] { self<Sprite3D>(env, thiz)->setImage(arg<m3g::Image2D>(env, image)); });
}
M3G_JNI(jobject, Sprite3D, getImage)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Sprite3D>(env, thiz)->getImage()); });
}
M3G_JNI(void, Sprite3D, setCrop)(JNIEnv* env, jobject thiz, jint x, jint y, jint width, jint height) {
    guard(env, [&] { self<Sprite3D>(env, thiz)->setCrop(x, y, width, height); });
}
M3G_JNI(jint, Sprite3D, getCropX)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Sprite3D>(env, thiz)->getCropX(); });
}
M3G_JNI(jint, Sprite3D, getCropY)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Sprite3D>(env, thiz)->getCropY(); });
}
M3G_JNI(jint, Sprite3D, getCropWidth)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Sprite3D>(env, thiz)->getCropWidth(); });
}
M3G_JNI(jint, Sprite3D, getCropHeight)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Sprite3D>(env, thiz)->getCropHeight(); });
}
