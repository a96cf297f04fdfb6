// javax.microedition.m3g.Node's native methods (JSR-184 1.1, Node).
#include <m3g/Node.h>

#include "Jni.h"
#include "Transforms.h"

using namespace m3gjni;
using m3g::Node;

M3G_JNI(jobject, Node, getParent)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Node>(env, thiz)->getParent()); });
}

// The transform is written only when the nodes share a scene graph (true).
M3G_JNI(jboolean, Node, getTransformTo)(JNIEnv* env, jobject thiz, jobject target, jobject transform) {
    return guard(env, [&]() -> jboolean {
        m3g::Transform m;
        const bool same = self<Node>(env, thiz)->getTransformTo(arg<Node>(env, target), transform ? &m : nullptr);
        if (same) store(env, transform, m);
        return static_cast<jboolean>(same);
    });
}

M3G_JNI(void, Node, setAlignment)(JNIEnv* env, jobject thiz, jobject zRef, jint zTarget, jobject yRef, jint yTarget) {
    guard(env, [&] {
        self<Node>(env, thiz)->setAlignment(arg<Node>(env, zRef), zTarget, arg<Node>(env, yRef), yTarget);
    });
}
M3G_JNI(void, Node, align)(JNIEnv* env, jobject thiz, jobject reference) {
    guard(env, [&] { self<Node>(env, thiz)->align(arg<Node>(env, reference)); });
}
M3G_JNI(jobject, Node, getAlignmentReference)(JNIEnv* env, jobject thiz, jint axis) {
    return guard(env, [&] { return peer(env, self<Node>(env, thiz)->getAlignmentReference(axis)); });
}
M3G_JNI(jint, Node, getAlignmentTarget)(JNIEnv* env, jobject thiz, jint axis) {
    return guard(env, [&] { return self<Node>(env, thiz)->getAlignmentTarget(axis); });
}

M3G_JNI(void, Node, setAlphaFactor)(JNIEnv* env, jobject thiz, jfloat alpha) {
    guard(env, [&] { self<Node>(env, thiz)->setAlphaFactor(alpha); });
}
M3G_JNI(jfloat, Node, getAlphaFactor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Node>(env, thiz)->getAlphaFactor(); });
}
M3G_JNI(void, Node, setRenderingEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<Node>(env, thiz)->setRenderingEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, Node, isRenderingEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Node>(env, thiz)->isRenderingEnabled()); });
}
M3G_JNI(void, Node, setPickingEnable)(JNIEnv* env, jobject thiz, jboolean enable) {
    guard(env, [&] { self<Node>(env, thiz)->setPickingEnable(enable == JNI_TRUE); });
}
M3G_JNI(jboolean, Node, isPickingEnabled)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Node>(env, thiz)->isPickingEnabled()); });
}
M3G_JNI(void, Node, setScope)(JNIEnv* env, jobject thiz, jint scope) {
    guard(env, [&] { self<Node>(env, thiz)->setScope(scope); });
}
M3G_JNI(jint, Node, getScope)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Node>(env, thiz)->getScope(); });
}
