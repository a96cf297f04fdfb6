#include "UserObjects.h"

#include <any>
#include <memory>
#include <mutex>
#include <unordered_set>
#include <vector>

#include "Jni.h"
#include "Peers.h"

namespace m3gjni {

namespace {

struct UserObject;
std::mutex gRegistryMutex;
std::unordered_set<UserObject*> gRegistry;

JNIEnv* currentEnv() noexcept {
    JNIEnv* env = nullptr;
    if (JavaVM* vm = javaVm()) vm->GetEnv(reinterpret_cast<void**>(&env), JNI_VERSION_1_8);
    return env;
}

/// The JNI reference to one user object, for one owner.
struct UserObject {
    jobject ref = nullptr;
    bool strong = true;
    const m3g::Object3D* owner = nullptr;

    UserObject(JNIEnv* env, jobject value, const m3g::Object3D* o) : ref(env->NewGlobalRef(value)), owner(o) {
        std::lock_guard lock(gRegistryMutex);
        gRegistry.insert(this);
    }
    ~UserObject() {
        {
            std::lock_guard lock(gRegistryMutex);
            gRegistry.erase(this);
        }
        // Without a Java thread (the JVM going away), the reference goes with it.
        if (JNIEnv* env = currentEnv()) {
            if (strong)
                env->DeleteGlobalRef(ref);
            else
                env->DeleteWeakGlobalRef(ref);
        }
    }
    UserObject(const UserObject&) = delete;
    UserObject& operator=(const UserObject&) = delete;

    jobject get(JNIEnv* env) const { return env->NewLocalRef(ref); }
    void hold(JNIEnv* env, bool wantStrong) {
        if (wantStrong == strong) return;
        if (wantStrong) {
            jobject g = env->NewGlobalRef(ref);  // null if already collected (cannot happen, see the header)
            env->DeleteWeakGlobalRef(ref);
            ref = g;
        } else {
            jobject w = env->NewWeakGlobalRef(ref);
            env->DeleteGlobalRef(ref);
            ref = w;
        }
        strong = wantStrong;
    }
};

using Slot = std::shared_ptr<UserObject>;

UserObject* slotOf(const m3g::Object3D* object) {
    const Slot* s = std::any_cast<Slot>(&object->getUserObject());
    return s ? s->get() : nullptr;
}

// Weak only while the peer alone holds the object (and holds the user object itself).
void recheck(JNIEnv* env, const m3g::Object3D* object, UserObject& u) {
    if (u.owner != object) return;  // a duplicate's copy before adoptDuplicates
    u.hold(env, !(object->getRefCount() == 1 && hasLivePeer(env, object)));
}

jobject hashtableOf(JNIEnv* env, const m3g::UserParameters& params) {
    jclass table = env->FindClass("java/util/Hashtable");
    jclass integer = env->FindClass("java/lang/Integer");
    if (!table || !integer) return nullptr;
    jmethodID ctor = env->GetMethodID(table, "<init>", "()V");
    jmethodID put = env->GetMethodID(table, "put", "(Ljava/lang/Object;Ljava/lang/Object;)Ljava/lang/Object;");
    jmethodID valueOf = env->GetStaticMethodID(integer, "valueOf", "(I)Ljava/lang/Integer;");
    jobject out = env->NewObject(table, ctor);
    if (!out) return nullptr;
    for (const auto& [id, bytes] : params) {
        jbyteArray value = env->NewByteArray(static_cast<jsize>(bytes.size()));
        if (!value) return nullptr;  // OutOfMemoryError pending
        env->SetByteArrayRegion(value, 0, static_cast<jsize>(bytes.size()), reinterpret_cast<const jbyte*>(bytes.data()));
        jobject key = env->CallStaticObjectMethod(integer, valueOf, static_cast<jint>(id));
        if (env->ExceptionCheck()) return nullptr;
        jobject previous = env->CallObjectMethod(out, put, key, value);
        if (env->ExceptionCheck()) return nullptr;
        env->DeleteLocalRef(previous);
        env->DeleteLocalRef(key);
        env->DeleteLocalRef(value);
    }
    return out;
}

}  // namespace

void setUserObject(JNIEnv* env, m3g::Object3D* object, jobject value) {
    if (!value) {
        object->setUserObject({});
        return;
    }
    auto slot = std::make_shared<UserObject>(env, value, object);
    UserObject& u = *slot;
    object->setUserObject(Slot(std::move(slot)));
    recheck(env, object, u);
}

jobject userObject(JNIEnv* env, m3g::Object3D* object) {
    if (UserObject* u = slotOf(object)) return u->get(env);
    if (const m3g::UserParameters* params = object->getUserParameters()) {
        jobject table = hashtableOf(env, *params);
        if (table) setUserObject(env, object, table);
        return table;
    }
    return nullptr;
}

void adoptDuplicates(JNIEnv* env, m3g::Object3D* copyRoot) {
    // Every object reachable from the copy whose slot names another owner
    // is a copy sharing its original's user object: a slot of its own.
    std::vector<m3g::Object3D*> stack{copyRoot};
    std::unordered_set<m3g::Object3D*> seen;
    while (!stack.empty()) {
        m3g::Object3D* o = stack.back();
        stack.pop_back();
        if (!seen.insert(o).second) continue;
        if (UserObject* u = slotOf(o); u && u->owner != o) {
            jobject value = u->get(env);
            setUserObject(env, o, value);
            env->DeleteLocalRef(value);
        }
        std::vector<m3g::Ref<m3g::Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
        o->getReferences(refs);
        for (auto& r : refs)
            if (r) stack.push_back(r.get());
    }
}

void recheckUserObject(JNIEnv* env, m3g::Object3D* object) noexcept {
    if (UserObject* u = slotOf(object)) recheck(env, object, *u);
}

void recheckAllUserObjects(JNIEnv* env) noexcept {
    std::lock_guard lock(gRegistryMutex);
    for (UserObject* u : gRegistry) recheck(env, u->owner, *u);
}

}  // namespace m3gjni
