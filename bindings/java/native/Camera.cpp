// javax.microedition.m3g.Camera's native methods (JSR-184 1.1, Camera).
#include <m3g/Camera.h>

#include "Jni.h"
#include "Arrays.h"
#include "Transforms.h"

using namespace m3gjni;
using m3g::Camera;

M3G_JNI(jlong, Camera, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<Camera>()); });
}

M3G_JNI(void, Camera, setPerspective)(JNIEnv* env, jobject thiz, jfloat fovy, jfloat aspect, jfloat near, jfloat far) {
    guard(env, [&] { self<Camera>(env, thiz)->setPerspective(fovy, aspect, near, far); });
}
M3G_JNI(void, Camera, setParallel)(JNIEnv* env, jobject thiz, jfloat height, jfloat aspect, jfloat near, jfloat far) {
    guard(env, [&] { self<Camera>(env, thiz)->setParallel(height, aspect, near, far); });
}
M3G_JNI(void, Camera, setGeneric)(JNIEnv* env, jobject thiz, jobject transform) {
    guard(env, [&] {
        m3g::Transform m;
        self<Camera>(env, thiz)->setGeneric(transformOf(env, transform, m) ? &m : nullptr);
    });
}

// Null is allowed: only the type is returned then.
M3G_JNI(jint, Camera, getProjection__Ljavax_microedition_m3g_Transform_2)(JNIEnv* env, jobject thiz, jobject transform) {
    return guard(env, [&]() -> jint {
        m3g::Transform m;
        const int type = self<Camera>(env, thiz)->getProjection(transform ? &m : nullptr);
        if (transform) store(env, transform, m);
        return type;
    });
}
M3G_JNI(jint, Camera, getProjection___3F)(JNIEnv* env, jobject thiz, jfloatArray params) {
    return guard(env, [&]() -> jint {
        SpanOut<jfloatArray> out(env, params, kWholeArray, SpanOut<jfloatArray>::Start::Values);
        const int type = self<Camera>(env, thiz)->getProjection(out.span());
        out.commit();
        return type;
    });
}
