// javax.microedition.m3g.KeyframeSequence's native methods (JSR-184 1.1, KeyframeSequence).
#include <m3g/KeyframeSequence.h>

#include "Jni.h"
#include "Arrays.h"

using namespace m3gjni;
using m3g::KeyframeSequence;

M3G_JNI(jlong, KeyframeSequence, create)(JNIEnv* env, jclass, jint numKeyframes, jint numComponents,
                                         jint interpolation) {
    return guard(env, [&] { return handleOf(m3g::make<KeyframeSequence>(numKeyframes, numComponents, interpolation)); });
}

// The value is copied; null reaches m3g-vk as null (its NullPointerException).
M3G_JNI(void, KeyframeSequence, setKeyframe)(JNIEnv* env, jobject thiz, jint index, jint time, jfloatArray value) {
    guard(env, [&] {
        SpanIn<jfloatArray> in(env, value);
        self<KeyframeSequence>(env, thiz)->setKeyframe(index, time, in.span());
    });
}
// Null is allowed: only the time is returned then.
M3G_JNI(jint, KeyframeSequence, getKeyframe)(JNIEnv* env, jobject thiz, jint index, jfloatArray value) {
    return guard(env, [&]() -> jint {
        SpanOut<jfloatArray> out(env, value, kWholeArray, SpanOut<jfloatArray>::Start::Values);
        const int time = self<KeyframeSequence>(env, thiz)->getKeyframe(index, out.span());
        out.commit();
        return time;
    });
}

M3G_JNI(void, KeyframeSequence, setValidRange)(JNIEnv* env, jobject thiz, jint first, jint last) {
    guard(env, [&] { self<KeyframeSequence>(env, thiz)->setValidRange(first, last); });
}
M3G_JNI(jint, KeyframeSequence, getValidRangeFirst)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getValidRangeFirst(); });
}
M3G_JNI(jint, KeyframeSequence, getValidRangeLast)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getValidRangeLast(); });
}
M3G_JNI(void, KeyframeSequence, setDuration)(JNIEnv* env, jobject thiz, jint duration) {
    guard(env, [&] { self<KeyframeSequence>(env, thiz)->setDuration(duration); });
}
M3G_JNI(jint, KeyframeSequence, getDuration)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getDuration(); });
}
M3G_JNI(void, KeyframeSequence, setRepeatMode)(JNIEnv* env, jobject thiz, jint mode) {
    guard(env, [&] { self<KeyframeSequence>(env, thiz)->setRepeatMode(mode); });
}
M3G_JNI(jint, KeyframeSequence, getRepeatMode)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getRepeatMode(); });
}
M3G_JNI(jint, KeyframeSequence, getComponentCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getComponentCount(); });
}
M3G_JNI(jint, KeyframeSequence, getInterpolationType)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getInterpolationType(); });
}
M3G_JNI(jint, KeyframeSequence, getKeyframeCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<KeyframeSequence>(env, thiz)->getKeyframeCount(); });
}
