// javax.microedition.m3g.Loader's native methods (JSR-184 1.1, Loader): the
// roots m3g::Loader returns, as peers.
#include <string>
#include <vector>

#include <m3g/Loader.h>

#include "Arrays.h"
#include "Jni.h"

using namespace m3gjni;

namespace {

jobjectArray peers(JNIEnv* env, const std::vector<m3g::Ref<m3g::Object3D>>& roots) {
    jobjectArray out = env->NewObjectArray(static_cast<jsize>(roots.size()), cache().object3D, nullptr);
    for (std::size_t i = 0; i < roots.size(); ++i) {
        jobject p = peer(env, roots[i]);
        env->SetObjectArrayElement(out, static_cast<jsize>(i), p);
        env->DeleteLocalRef(p);
    }
    return out;
}

}  // namespace

M3G_JNI(jobjectArray, Loader, loadFile)(JNIEnv* env, jclass, jstring path) {
    return guard(env, [&]() -> jobjectArray {
        const char* chars = env->GetStringUTFChars(path, nullptr);
        const std::string name(chars);
        env->ReleaseStringUTFChars(path, chars);
        return peers(env, m3g::Loader::load(name));
    });
}

M3G_JNI(jobjectArray, Loader, loadBytes)(JNIEnv* env, jclass, jbyteArray data, jint offset) {
    return guard(env, [&]() -> jobjectArray {
        SpanIn<jbyteArray> bytes = requiredIn(env, data, "Loader.load");
        return peers(env, m3g::Loader::load(bytes.as<std::uint8_t>(), offset));
    });
}
