// javax.microedition.m3g.Transform's native methods (JSR-184 1.1, Transform).
#include <string>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/VertexArray.h>

#include "Arrays.h"
#include "Jni.h"
#include "Transforms.h"

using namespace m3gjni;

namespace m3gjni {

namespace {
jfieldID matrixField(JNIEnv* env, jobject transform) {
    static jfieldID field = [&] {
        jclass cls = env->GetObjectClass(transform);
        return env->GetFieldID(cls, "m", "[F");
    }();
    return field;
}
}  // namespace

bool transformOf(JNIEnv* env, jobject transform, m3g::Transform& out) {
    if (!transform) return false;
    auto array = static_cast<jfloatArray>(env->GetObjectField(transform, matrixField(env, transform)));
    float m[16];
    env->GetFloatArrayRegion(array, 0, 16, m);
    env->DeleteLocalRef(array);
    out.set(std::span<const float>(m, 16));
    return true;
}

m3g::Transform transformOf(JNIEnv* env, jobject transform, const char* where) {
    m3g::Transform t;
    if (!transformOf(env, transform, t)) throw m3g::NullPointerException(std::string(where) + ": the transform is null");
    return t;
}

void store(JNIEnv* env, jobject transform, const m3g::Transform& value) {
    float m[16];
    value.get(std::span<float>(m, 16));
    auto array = static_cast<jfloatArray>(env->GetObjectField(transform, matrixField(env, transform)));
    env->SetFloatArrayRegion(array, 0, 16, m);
    env->DeleteLocalRef(array);
}

}  // namespace m3gjni

namespace {
// Applies `op` to this Transform's matrix.
template <class Op>
void update(JNIEnv* env, jobject thiz, Op&& op) {
    guard(env, [&] {
        m3g::Transform t = transformOf(env, thiz, "Transform");
        op(t);
        store(env, thiz, t);
    });
}
}  // namespace

M3G_JNI(void, Transform, setIdentity)(JNIEnv* env, jobject thiz) {
    update(env, thiz, [](m3g::Transform& t) { t.setIdentity(); });
}

M3G_JNI(void, Transform, set__Ljavax_microedition_m3g_Transform_2)(JNIEnv* env, jobject thiz, jobject other) {
    update(env, thiz, [&](m3g::Transform& t) {
        m3g::Transform o;
        t.set(transformOf(env, other, o) ? &o : nullptr);
    });
}

M3G_JNI(void, Transform, set___3F)(JNIEnv* env, jobject thiz, jfloatArray matrix) {
    update(env, thiz, [&](m3g::Transform& t) { t.set(requiredIn(env, matrix, "Transform.set").span()); });
}

M3G_JNI(void, Transform, get)(JNIEnv* env, jobject thiz, jfloatArray matrix) {
    guard(env, [&] {
        const m3g::Transform t = transformOf(env, thiz, "Transform");
        FloatsInOut out(env, matrix, "Transform.get");
        t.get(out.span());
        out.commit();
    });
}

M3G_JNI(void, Transform, invert)(JNIEnv* env, jobject thiz) {
    update(env, thiz, [](m3g::Transform& t) { t.invert(); });
}

M3G_JNI(void, Transform, transpose)(JNIEnv* env, jobject thiz) {
    update(env, thiz, [](m3g::Transform& t) { t.transpose(); });
}

M3G_JNI(void, Transform, postMultiply)(JNIEnv* env, jobject thiz, jobject other) {
    update(env, thiz, [&](m3g::Transform& t) {
        m3g::Transform o;
        t.postMultiply(transformOf(env, other, o) ? &o : nullptr);
    });
}

M3G_JNI(void, Transform, postScale)(JNIEnv* env, jobject thiz, jfloat x, jfloat y, jfloat z) {
    update(env, thiz, [&](m3g::Transform& t) { t.postScale(x, y, z); });
}

M3G_JNI(void, Transform, postRotate)(JNIEnv* env, jobject thiz, jfloat a, jfloat x, jfloat y, jfloat z) {
    update(env, thiz, [&](m3g::Transform& t) { t.postRotate(a, x, y, z); });
}

M3G_JNI(void, Transform, postRotateQuat)(JNIEnv* env, jobject thiz, jfloat x, jfloat y, jfloat z, jfloat w) {
    update(env, thiz, [&](m3g::Transform& t) { t.postRotateQuat(x, y, z, w); });
}

M3G_JNI(void, Transform, postTranslate)(JNIEnv* env, jobject thiz, jfloat x, jfloat y, jfloat z) {
    update(env, thiz, [&](m3g::Transform& t) { t.postTranslate(x, y, z); });
}

M3G_JNI(void, Transform, transform__Ljavax_microedition_m3g_VertexArray_2_3FZ)(JNIEnv* env, jobject thiz, jobject in,
                                                                              jfloatArray out, jboolean w) {
    guard(env, [&] {
        const m3g::Transform t = transformOf(env, thiz, "Transform");
        FloatsInOut result(env, out, "Transform.transform");
        t.transform(arg<m3g::VertexArray>(env, in), result.span(), w == JNI_TRUE);
        result.commit();
    });
}

M3G_JNI(void, Transform, transform___3F)(JNIEnv* env, jobject thiz, jfloatArray vectors) {
    guard(env, [&] {
        const m3g::Transform t = transformOf(env, thiz, "Transform");
        FloatsInOut v(env, vectors, "Transform.transform");
        t.transform(v.span());
        v.commit();
    });
}
