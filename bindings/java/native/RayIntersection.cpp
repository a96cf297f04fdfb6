// javax.microedition.m3g.RayIntersection's native methods (JSR-184 1.1,
// RayIntersection): a native m3g::RayIntersection owned by the Java object
// (its `handle` field, freed by its Cleaner), filled by Group.pick
// (storePick). The intersected node is kept by the Java object as its peer,
// never by the native result, so that freeing the result on the Cleaner's
// thread releases no M3G object there (Peers.h: releases happen on calling
// threads).
#include <cstdint>

#include <m3g/RayIntersection.h>

#include "Jni.h"
#include "Arrays.h"
#include "RayIntersections.h"

using namespace m3gjni;
using m3g::RayIntersection;

namespace {
struct Fields {
    jfieldID handle = nullptr;       // long
    jfieldID intersected = nullptr;  // Node
};
const Fields& fields(JNIEnv* env) {
    static const Fields f = [env] {
        Fields r;
        jclass cls = env->FindClass("javax/microedition/m3g/RayIntersection");
        if (!cls) return r;
        r.handle = env->GetFieldID(cls, "handle", "J");
        r.intersected = env->GetFieldID(cls, "intersected", "Ljavax/microedition/m3g/Node;");
        env->DeleteLocalRef(cls);
        return r;
    }();
    return f;
}
RayIntersection* fromHandle(jlong handle) {
    return reinterpret_cast<RayIntersection*>(static_cast<std::intptr_t>(handle));
}
}  // namespace

namespace m3gjni {

RayIntersection* rayIntersectionOf(JNIEnv* env, jobject ri) {
    return fromHandle(env->GetLongField(ri, fields(env).handle));
}

void storePick(JNIEnv* env, jobject ri, const RayIntersection& result) {
    jobject node = peer(env, result.getIntersected());
    if (env->ExceptionCheck()) return;  // the peer could not be made; ri stays as it was
    RayIntersection* native = rayIntersectionOf(env, ri);
    *native = result;
    native->setIntersected(nullptr, result.getDistance(), result.getSubmeshIndex());
    env->SetObjectField(ri, fields(env).intersected, node);
    env->DeleteLocalRef(node);
}

}  // namespace m3gjni

M3G_JNI(jlong, RayIntersection, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return static_cast<jlong>(reinterpret_cast<std::intptr_t>(new RayIntersection())); });
}

// The Cleaner's thread: the result holds no M3G object (see above).
M3G_JNI(void, RayIntersection, destroy)(JNIEnv*, jclass, jlong handle) {
    delete fromHandle(handle);
}

M3G_JNI(jfloat, RayIntersection, getDistance)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getDistance(); });
}
M3G_JNI(jint, RayIntersection, getSubmeshIndex)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getSubmeshIndex(); });
}
M3G_JNI(jfloat, RayIntersection, getTextureS)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getTextureS(index); });
}
M3G_JNI(jfloat, RayIntersection, getTextureT)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getTextureT(index); });
}
M3G_JNI(jfloat, RayIntersection, getNormalX)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getNormalX(); });
}
M3G_JNI(jfloat, RayIntersection, getNormalY)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getNormalY(); });
}
M3G_JNI(jfloat, RayIntersection, getNormalZ)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return rayIntersectionOf(env, thiz)->getNormalZ(); });
}
M3G_JNI(void, RayIntersection, getRay)(JNIEnv* env, jobject thiz, jfloatArray ray) {
    guard(env, [&] {
        FloatsInOut out(env, ray, "RayIntersection.getRay");
        rayIntersectionOf(env, thiz)->getRay(out.span());
        out.commit();
    });
}
