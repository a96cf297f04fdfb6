// javax.microedition.m3g.Object3D's native methods (JSR-184 1.1, Object3D).
#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/Object3D.h>

#include "Jni.h"
#include "UserObjects.h"

using namespace m3gjni;
using m3g::Object3D;

M3G_JNI(jint, Object3D, animate)(JNIEnv* env, jobject thiz, jint time) {
    return guard(env, [&] { return self<Object3D>(env, thiz)->animate(time); });
}

M3G_JNI(jobject, Object3D, duplicateNative)(JNIEnv* env, jobject thiz) {
    return guard(env, [&]() -> jobject {
        m3g::Ref<Object3D> copy = self<Object3D>(env, thiz)->duplicate();
        adoptDuplicates(env, copy.get());
        return peer(env, copy);
    });
}

M3G_JNI(jobject, Object3D, find)(JNIEnv* env, jobject thiz, jint userID) {
    return guard(env, [&] { return peer(env, self<Object3D>(env, thiz)->find(userID)); });
}

M3G_JNI(jint, Object3D, getReferences)(JNIEnv* env, jobject thiz, jobjectArray references) {
    return guard(env, [&]() -> jint {
        Object3D* o = self<Object3D>(env, thiz);
        const int n = o->getReferences();
        if (!references) return n;
        if (env->GetArrayLength(references) < n)
            throw m3g::IllegalArgumentException("Object3D.getReferences: the array holds " +
                                                std::to_string(env->GetArrayLength(references)) +
                                                " elements, fewer than the " + std::to_string(n) + " references");
        std::vector<m3g::Ref<Object3D>> refs(static_cast<std::size_t>(n));
        o->getReferences(refs);
        for (int i = 0; i < n; ++i) {
            jobject p = peer(env, refs[static_cast<std::size_t>(i)]);
            env->SetObjectArrayElement(references, i, p);
            env->DeleteLocalRef(p);
        }
        return n;
    });
}

M3G_JNI(void, Object3D, setUserID)(JNIEnv* env, jobject thiz, jint id) {
    guard(env, [&] { self<Object3D>(env, thiz)->setUserID(id); });
}

M3G_JNI(jint, Object3D, getUserID)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Object3D>(env, thiz)->getUserID(); });
}

M3G_JNI(void, Object3D, setUserObjectNative)(JNIEnv* env, jobject thiz, jobject value) {
    guard(env, [&] { setUserObject(env, self<Object3D>(env, thiz), value); });
}

M3G_JNI(jobject, Object3D, getUserObject)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return userObject(env, self<Object3D>(env, thiz)); });
}

M3G_JNI(void, Object3D, addAnimationTrack)(JNIEnv* env, jobject thiz, jobject track) {
    guard(env, [&] { self<Object3D>(env, thiz)->addAnimationTrack(arg<m3g::AnimationTrack>(env, track)); });
}

M3G_JNI(jobject, Object3D, getAnimationTrack)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<Object3D>(env, thiz)->getAnimationTrack(index)); });
}

M3G_JNI(void, Object3D, removeAnimationTrack)(JNIEnv* env, jobject thiz, jobject track) {
    guard(env, [&] { self<Object3D>(env, thiz)->removeAnimationTrack(arg<m3g::AnimationTrack>(env, track)); });
}

M3G_JNI(jint, Object3D, getAnimationTrackCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Object3D>(env, thiz)->getAnimationTrackCount(); });
}
