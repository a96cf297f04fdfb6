// The JNI layer's common parts (bindings/java, docs/java.md): native methods
// are thin wrappers that unwrap their Java arguments, call m3g-vk, and
// wrap results. Here:
//   - M3G_JNI(ret, Class, name): the exported name of a native method of
//     javax.microedition.m3g.Class;
//   - guard(): runs a call, turning m3g-vk's C++ exceptions into the Java
//     exceptions JSR-184 1.1 names, with the C++ message;
//   - self<T>() / arg<T>(): the native object behind a Java peer;
//   - peer(): the one Java object of a native object (made on first use).
#pragma once

#include <jni.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

#include <m3g/Object3D.h>
#include <m3g/Ref.h>

#define M3G_JNI(ret, cls, name) extern "C" JNIEXPORT ret JNICALL Java_javax_microedition_m3g_##cls##_##name

namespace m3gjni {

/// Thrown by native code when a JNI call left a Java exception pending (an
/// OutOfMemoryError, a class that failed to load): guard() lets that one stand.
struct JavaExceptionPending {};

/// A pending Java exception of class `cls` ("java/lang/IllegalArgumentException").
void throwJava(JNIEnv* env, const char* cls, const std::string& message);

/// Throws in Java what the current C++ exception is (call in a catch block).
void rethrowAsJava(JNIEnv* env) noexcept;

/// Bookkeeping of the current call (guard()): the M3G objects passed in,
/// whose user objects' hold is rechecked afterwards (UserObjects.h), and the
/// releases of collected peers, done on a calling thread (Peers.h).
void noteArgument(m3g::Object3D* object) noexcept;
void afterCall(JNIEnv* env) noexcept;

/// Runs `f` and returns its result; a C++ exception becomes the matching
/// Java exception and the result is R{} (Java ignores it then). Arguments
/// unwrapped during the call are rechecked for their user objects' hold
/// afterwards (UserObjects.h).
template <class F>
auto guard(JNIEnv* env, F&& f) noexcept -> decltype(f()) {
    using R = decltype(f());
    try {
        if constexpr (std::is_void_v<R>) {
            f();
            afterCall(env);
        } else {
            R r = f();
            afterCall(env);
            return r;
        }
    } catch (...) {
        rethrowAsJava(env);
        afterCall(env);
        if constexpr (!std::is_void_v<R>) return R{};
    }
}

/// The native object a peer stands for (its `handle` field); null for null.
m3g::Object3D* objectOf(JNIEnv* env, jobject peer) noexcept;

/// `peer`'s native object as T (the peer's Java class guarantees the type);
/// null for a null peer. Remembered for afterCall().
template <class T>
T* arg(JNIEnv* env, jobject peer) {
    m3g::Object3D* o = objectOf(env, peer);
    noteArgument(o);
    return static_cast<T*>(o);
}

/// The receiver of an instance method (never null). Not remembered: a call
/// gives its receiver no new holder (its arguments may get one: itself).
template <class T>
T* self(JNIEnv* env, jobject peer) {
    return static_cast<T*>(objectOf(env, peer));
}

/// The Java peer of `object` (a local reference): the existing one while it
/// is alive, else a new object of the Java class of the same name; null for
/// null.
jobject peer(JNIEnv* env, m3g::Object3D* object);
inline jobject peer(JNIEnv* env, const m3g::Ref<m3g::Object3D>& object) { return peer(env, object.get()); }
template <class T>
jobject peer(JNIEnv* env, const m3g::Ref<T>& object) {
    return peer(env, static_cast<m3g::Object3D*>(object.get()));
}

/// A handle for a new peer: one reference to `object` owned by the Java
/// object the handle is given to (Object3D's constructor registers it).
template <class T>
jlong handleOf(const m3g::Ref<T>& object) {
    m3g::Object3D* o = object.get();
    o->addRef();
    return static_cast<jlong>(reinterpret_cast<std::intptr_t>(o));
}

/// java.lang.Class objects and member IDs, resolved once at JNI_OnLoad.
struct Cache {
    jclass object3D;
    jfieldID handle;          // Object3D.handle (long)
    jfieldID userObjectHold;  // Object3D.userObjectHold (Object)
};
const Cache& cache() noexcept;
JavaVM* javaVm() noexcept;

}  // namespace m3gjni
