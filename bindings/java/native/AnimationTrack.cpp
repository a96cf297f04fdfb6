// javax.microedition.m3g.AnimationTrack's native methods (JSR-184 1.1, AnimationTrack).
#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>

#include "Jni.h"

using namespace m3gjni;
using m3g::AnimationTrack;

M3G_JNI(jlong, AnimationTrack, create)(JNIEnv* env, jclass, jobject sequence, jint property) {
    return guard(env, [&] {
        return handleOf(m3g::make<AnimationTrack>(arg<m3g::KeyframeSequence>(env, sequence), property));
    });
}

M3G_JNI(void, AnimationTrack, setController)(JNIEnv* env, jobject thiz, jobject controller) {
    guard(env, [&] { self<AnimationTrack>(env, thiz)->setController(arg<m3g::AnimationController>(env, controller)); });
}
M3G_JNI(jobject, AnimationTrack, getController)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<AnimationTrack>(env, thiz)->getController()); });
}
M3G_JNI(jobject, AnimationTrack, getKeyframeSequence)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<AnimationTrack>(env, thiz)->getKeyframeSequence()); });
}
M3G_JNI(jint, AnimationTrack, getTargetProperty)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<AnimationTrack>(env, thiz)->getTargetProperty(); });
}
