#include "Peers.h"

#include <atomic>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "Jni.h"
#include "UserObjects.h"

namespace m3gjni {

namespace {

Cache gCache{};
JavaVM* gVm = nullptr;

std::mutex gPeersMutex;
std::unordered_map<const m3g::Object3D*, jweak> gPeers;  // object -> its (latest) peer
std::vector<m3g::Object3D*> gReleases;                    // handles of collected peers
std::atomic<bool> gReleasesPending{false};                // gReleases non-empty: most calls need no lock
std::unordered_map<std::string, std::pair<jclass, jmethodID>> gClasses;  // "Mesh" -> class, (J)V constructor

thread_local std::vector<m3g::Object3D*> tArguments;

}  // namespace

const Cache& cache() noexcept { return gCache; }
JavaVM* javaVm() noexcept { return gVm; }

m3g::Object3D* objectOf(JNIEnv* env, jobject peer) noexcept {
    if (!peer) return nullptr;
    return reinterpret_cast<m3g::Object3D*>(static_cast<std::intptr_t>(env->GetLongField(peer, gCache.handle)));
}

void noteArgument(m3g::Object3D* object) noexcept {
    if (object) tArguments.push_back(object);
}

void afterCall(JNIEnv* env) noexcept {
    if (!tArguments.empty()) {
        for (m3g::Object3D* o : tArguments) recheckUserObject(env, o);
        tArguments.clear();
    }
    drainReleases(env);
}

bool hasLivePeer(JNIEnv* env, const m3g::Object3D* object) {
    std::lock_guard lock(gPeersMutex);
    const auto it = gPeers.find(object);
    return it != gPeers.end() && !env->IsSameObject(it->second, nullptr);
}

long peerCount() noexcept {
    std::lock_guard lock(gPeersMutex);
    return static_cast<long>(gPeers.size());
}

jobject peer(JNIEnv* env, m3g::Object3D* object) {
    if (!object) return nullptr;
    {
        std::lock_guard lock(gPeersMutex);
        const auto it = gPeers.find(object);
        if (it != gPeers.end())
            if (jobject live = env->NewLocalRef(it->second)) return live;
    }
    // None, or collected: a new peer of the Java class of the same name,
    // through its package-private (long handle) constructor, which attaches.
    std::pair<jclass, jmethodID> cls{};
    {
        std::lock_guard lock(gPeersMutex);
        const std::string name = object->getClassName();
        auto it = gClasses.find(name);
        if (it == gClasses.end()) {
            jclass local = env->FindClass(("javax/microedition/m3g/" + name).c_str());
            if (!local) throw JavaExceptionPending{};  // NoClassDefFoundError
            jmethodID ctor = env->GetMethodID(local, "<init>", "(J)V");
            if (!ctor) throw JavaExceptionPending{};
            it = gClasses.emplace(name, std::make_pair(static_cast<jclass>(env->NewGlobalRef(local)), ctor)).first;
            env->DeleteLocalRef(local);
        }
        cls = it->second;
    }
    object->addRef();  // the new peer's reference
    jobject p = env->NewObject(cls.first, cls.second, static_cast<jlong>(reinterpret_cast<std::intptr_t>(object)));
    if (!p) {
        object->release();
        throw JavaExceptionPending{};
    }
    return p;
}

void drainReleases(JNIEnv* env) noexcept {
    if (!gReleasesPending.load(std::memory_order_acquire)) return;
    std::vector<m3g::Object3D*> releases;
    {
        std::lock_guard lock(gPeersMutex);
        gReleasesPending.store(false, std::memory_order_relaxed);
        if (gReleases.empty()) return;
        releases.swap(gReleases);
        // A table entry goes with its peer, unless a newer peer replaced it.
        for (m3g::Object3D* o : releases) {
            const auto it = gPeers.find(o);
            if (it != gPeers.end() && env->IsSameObject(it->second, nullptr)) {
                env->DeleteWeakGlobalRef(it->second);
                gPeers.erase(it);
            }
        }
    }
    for (m3g::Object3D* o : releases) o->release();  // may free it and what it held
    recheckAllUserObjects(env);
}

}  // namespace m3gjni

using namespace m3gjni;

extern "C" JNIEXPORT jint JNICALL JNI_OnLoad(JavaVM* vm, void*) {
    gVm = vm;
    JNIEnv* env = nullptr;
    if (vm->GetEnv(reinterpret_cast<void**>(&env), JNI_VERSION_1_8) != JNI_OK) return JNI_ERR;
    jclass object3D = env->FindClass("javax/microedition/m3g/Object3D");
    if (!object3D) return JNI_ERR;
    gCache.object3D = static_cast<jclass>(env->NewGlobalRef(object3D));
    gCache.handle = env->GetFieldID(object3D, "handle", "J");
    gCache.userObjectHold = env->GetFieldID(object3D, "userObjectHold", "Ljava/lang/Object;");
    if (!gCache.handle || !gCache.userObjectHold) return JNI_ERR;
    return JNI_VERSION_1_8;
}

// Object3D(long handle) registers its peer: the handle's reference is the peer's.
M3G_JNI(void, Object3D, attach)(JNIEnv* env, jobject self) {
    m3g::Object3D* o = objectOf(env, self);
    std::lock_guard lock(gPeersMutex);
    jweak& slot = gPeers[o];
    // An older peer's entry (collected, release pending) is replaced; its
    // release then leaves this one.
    if (slot) env->DeleteWeakGlobalRef(slot);
    slot = env->NewWeakGlobalRef(self);
}

// The Cleaner of a collected peer (any thread): queued for the next call.
M3G_JNI(void, Object3D, release)(JNIEnv*, jclass, jlong handle) {
    std::lock_guard lock(gPeersMutex);
    gReleases.push_back(reinterpret_cast<m3g::Object3D*>(static_cast<std::intptr_t>(handle)));
    gReleasesPending.store(true, std::memory_order_release);
}

M3G_JNI(jlong, Object3D, nativePeerCount)(JNIEnv* env, jclass) {
    drainReleases(env);
    return peerCount();
}
