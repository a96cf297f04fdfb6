// javax.microedition.m3g.World's native methods (JSR-184 1.1, World).
#include <m3g/World.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::World;

M3G_JNI(jlong, World, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<World>()); });
}

M3G_JNI(void, World, setActiveCamera)(JNIEnv* env, jobject thiz, jobject camera) {
    guard(env, [&] { self<World>(env, thiz)->setActiveCamera(arg<m3g::Camera>(env, camera)); });
}
M3G_JNI(jobject, World, getActiveCamera)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<World>(env, thiz)->getActiveCamera()); });
}
M3G_JNI(void, World, setBackground)(JNIEnv* env, jobject thiz, jobject background) {
    guard(env, [&] { self<World>(env, thiz)->setBackground(arg<m3g::Background>(env, background)); });
}
M3G_JNI(jobject, World, getBackground)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<World>(env, thiz)->getBackground()); });
}
