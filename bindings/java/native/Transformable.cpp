// javax.microedition.m3g.Transformable's native methods (JSR-184 1.1, Transformable).
#include <m3g/Transformable.h>

#include "Jni.h"
#include "Arrays.h"
#include "Transforms.h"

using namespace m3gjni;
using m3g::Transformable;

namespace {
// A getter filling a float[] (NPE for null, IAE if short, from m3g-vk).
template <class Get>
void getInto(JNIEnv* env, jfloatArray array, const char* where, Get&& get) {
    FloatsInOut out(env, array, where);
    get(out.span());
    out.commit();
}
}  // namespace

M3G_JNI(void, Transformable, setOrientation)(JNIEnv* env, jobject thiz, jfloat angle, jfloat ax, jfloat ay, jfloat az) {
    guard(env, [&] { self<Transformable>(env, thiz)->setOrientation(angle, ax, ay, az); });
}
M3G_JNI(void, Transformable, postRotate)(JNIEnv* env, jobject thiz, jfloat angle, jfloat ax, jfloat ay, jfloat az) {
    guard(env, [&] { self<Transformable>(env, thiz)->postRotate(angle, ax, ay, az); });
}
M3G_JNI(void, Transformable, preRotate)(JNIEnv* env, jobject thiz, jfloat angle, jfloat ax, jfloat ay, jfloat az) {
    guard(env, [&] { self<Transformable>(env, thiz)->preRotate(angle, ax, ay, az); });
}
M3G_JNI(void, Transformable, getOrientation)(JNIEnv* env, jobject thiz, jfloatArray angleAxis) {
    guard(env, [&] {
        Transformable* t = self<Transformable>(env, thiz);
        getInto(env, angleAxis, "Transformable.getOrientation", [&](std::span<float> s) { t->getOrientation(s); });
    });
}

M3G_JNI(void, Transformable, setScale)(JNIEnv* env, jobject thiz, jfloat sx, jfloat sy, jfloat sz) {
    guard(env, [&] { self<Transformable>(env, thiz)->setScale(sx, sy, sz); });
}
M3G_JNI(void, Transformable, scale)(JNIEnv* env, jobject thiz, jfloat sx, jfloat sy, jfloat sz) {
    guard(env, [&] { self<Transformable>(env, thiz)->scale(sx, sy, sz); });
}
M3G_JNI(void, Transformable, getScale)(JNIEnv* env, jobject thiz, jfloatArray xyz) {
    guard(env, [&] {
        Transformable* t = self<Transformable>(env, thiz);
        getInto(env, xyz, "Transformable.getScale", [&](std::span<float> s) { t->getScale(s); });
    });
}

M3G_JNI(void, Transformable, setTranslation)(JNIEnv* env, jobject thiz, jfloat tx, jfloat ty, jfloat tz) {
    guard(env, [&] { self<Transformable>(env, thiz)->setTranslation(tx, ty, tz); });
}
M3G_JNI(void, Transformable, translate)(JNIEnv* env, jobject thiz, jfloat tx, jfloat ty, jfloat tz) {
    guard(env, [&] { self<Transformable>(env, thiz)->translate(tx, ty, tz); });
}
M3G_JNI(void, Transformable, getTranslation)(JNIEnv* env, jobject thiz, jfloatArray xyz) {
    guard(env, [&] {
        Transformable* t = self<Transformable>(env, thiz);
        getInto(env, xyz, "Transformable.getTranslation", [&](std::span<float> s) { t->getTranslation(s); });
    });
}

M3G_JNI(void, Transformable, setTransform)(JNIEnv* env, jobject thiz, jobject transform) {
    guard(env, [&] {
        m3g::Transform m;
        self<Transformable>(env, thiz)->setTransform(transformOf(env, transform, m) ? &m : nullptr);
    });
}
M3G_JNI(void, Transformable, getTransform)(JNIEnv* env, jobject thiz, jobject transform) {
    guard(env, [&] {
        m3g::Transform m;
        self<Transformable>(env, thiz)->getTransform(transform ? &m : nullptr);
        store(env, transform, m);
    });
}
M3G_JNI(void, Transformable, getCompositeTransform)(JNIEnv* env, jobject thiz, jobject transform) {
    guard(env, [&] {
        m3g::Transform m;
        self<Transformable>(env, thiz)->getCompositeTransform(transform ? &m : nullptr);
        store(env, transform, m);
    });
}
