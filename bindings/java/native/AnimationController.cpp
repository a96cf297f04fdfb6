// javax.microedition.m3g.AnimationController's native methods (JSR-184 1.1, AnimationController).
#include <m3g/AnimationController.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::AnimationController;

M3G_JNI(jlong, AnimationController, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<AnimationController>()); });
}

M3G_JNI(void, AnimationController, setActiveInterval)(JNIEnv* env, jobject thiz, jint start, jint end) {
    guard(env, [&] { self<AnimationController>(env, thiz)->setActiveInterval(start, end); });
}
M3G_JNI(jint, AnimationController, getActiveIntervalStart)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getActiveIntervalStart(); });
}
M3G_JNI(jint, AnimationController, getActiveIntervalEnd)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getActiveIntervalEnd(); });
}
M3G_JNI(void, AnimationController, setSpeed)(JNIEnv* env, jobject thiz, jfloat speed, jint worldTime) {
    guard(env, [&] { self<AnimationController>(env, thiz)->setSpeed(speed, worldTime); });
}
M3G_JNI(jfloat, AnimationController, getSpeed)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getSpeed(); });
}
M3G_JNI(void, AnimationController, setPosition)(JNIEnv* env, jobject thiz, jfloat sequenceTime, jint worldTime) {
    guard(env, [&] { self<AnimationController>(env, thiz)->setPosition(sequenceTime, worldTime); });
}
M3G_JNI(jfloat, AnimationController, getPosition)(JNIEnv* env, jobject thiz, jint worldTime) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getPosition(worldTime); });
}
M3G_JNI(jint, AnimationController, getRefWorldTime)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getRefWorldTime(); });
}
M3G_JNI(void, AnimationController, setWeight)(JNIEnv* env, jobject thiz, jfloat weight) {
    guard(env, [&] { self<AnimationController>(env, thiz)->setWeight(weight); });
}
M3G_JNI(jfloat, AnimationController, getWeight)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationController>(env, thiz)->getWeight(); });
}
