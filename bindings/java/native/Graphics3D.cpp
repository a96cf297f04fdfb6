// javax.microedition.m3g.Graphics3D's native methods (JSR-184 1.1,
// Graphics3D). Each Java Graphics3D (one per thread) drives one native
// Graphics3D; targets other than Image2D are drawn in a native Graphics
// whose pixels the Java side copies from and back to the target.
#include <atomic>
#include <cstring>
#include <memory>
#include <string>
#include <variant>

#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/Camera.h>
#include <m3g/Graphics.h>
#include <m3g/Graphics3D.h>
#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Light.h>
#include <m3g/Node.h>
#include <m3g/VertexBuffer.h>
#include <m3g/World.h>

#include "Arrays.h"
#include "Jni.h"
#include "Transforms.h"

using namespace m3gjni;
using m3g::Graphics3D;

namespace {

Graphics3D* g3d(jlong handle) { return reinterpret_cast<Graphics3D*>(static_cast<std::intptr_t>(handle)); }
m3g::Graphics* surfaceOf(jlong handle) { return reinterpret_cast<m3g::Graphics*>(static_cast<std::intptr_t>(handle)); }
jlong toHandle(const void* p) { return static_cast<jlong>(reinterpret_cast<std::intptr_t>(p)); }

std::atomic<bool> gProcessInstanceTaken{false};

// A Transform argument that may be null (identity where the spec allows it).
struct OptionalTransform {
    m3g::Transform value;
    bool present;
    OptionalTransform(JNIEnv* env, jobject t) : present(transformOf(env, t, value)) {}
    const m3g::Transform* get() const { return present ? &value : nullptr; }
};

}  // namespace

#define G3D(name) M3G_JNI(void, Graphics3D, name)

// made[0]: the handle; made[1]: 1 when the Java object owns it (not the process-wide one).
M3G_JNI(void, Graphics3D, acquire)(JNIEnv* env, jclass, jlongArray made) {
    guard(env, [&] {
        jlong out[2];
        if (!gProcessInstanceTaken.exchange(true)) {
            out[0] = toHandle(Graphics3D::getInstance());
            out[1] = 0;
        } else {
            out[0] = toHandle(Graphics3D::create().release());
            out[1] = 1;
        }
        env->SetLongArrayRegion(made, 0, 2, out);
    });
}

M3G_JNI(void, Graphics3D, destroy)(JNIEnv*, jclass, jlong g) { delete g3d(g); }

M3G_JNI(jlong, Graphics3D, createSurface)(JNIEnv* env, jclass, jint width, jint height) {
    return guard(env, [&] {
        auto* surface = new m3g::Graphics(width, height);
        surface->addRef();
        return toHandle(surface);
    });
}

M3G_JNI(void, Graphics3D, destroySurface)(JNIEnv*, jclass, jlong surface) { surfaceOf(surface)->release(); }

M3G_JNI(void, Graphics3D, fillProperties)(JNIEnv* env, jclass, jobject table) {
    guard(env, [&] {
        jclass hashtable = env->GetObjectClass(table);
        jmethodID put = env->GetMethodID(hashtable, "put", "(Ljava/lang/Object;Ljava/lang/Object;)Ljava/lang/Object;");
        jclass booleanClass = env->FindClass("java/lang/Boolean");
        jclass integerClass = env->FindClass("java/lang/Integer");
        jmethodID booleanOf = env->GetStaticMethodID(booleanClass, "valueOf", "(Z)Ljava/lang/Boolean;");
        jmethodID integerOf = env->GetStaticMethodID(integerClass, "valueOf", "(I)Ljava/lang/Integer;");
        for (const auto& [name, value] : Graphics3D::getProperties()) {
            jobject v = nullptr;
            if (const bool* b = std::get_if<bool>(&value))
                v = env->CallStaticObjectMethod(booleanClass, booleanOf, static_cast<jboolean>(*b));
            else if (const int* i = std::get_if<int>(&value))
                v = env->CallStaticObjectMethod(integerClass, integerOf, static_cast<jint>(*i));
            else
                v = env->NewStringUTF(std::get<std::string>(value).c_str());
            if (env->ExceptionCheck()) return;  // out of memory: the Java exception stands
            jstring key = env->NewStringUTF(name.c_str());
            jobject previous = key ? env->CallObjectMethod(table, put, key, v) : nullptr;
            if (env->ExceptionCheck()) return;
            env->DeleteLocalRef(previous);
            env->DeleteLocalRef(key);
            env->DeleteLocalRef(v);
        }
    });
}

M3G_JNI(void, Graphics3D, bindImage)(JNIEnv* env, jclass, jlong g, jobject image, jboolean depth, jint hints) {
    guard(env, [&] { g3d(g)->bindTarget(arg<m3g::Image2D>(env, image), depth == JNI_TRUE, hints); });
}

M3G_JNI(void, Graphics3D, bindSurface)(JNIEnv* env, jclass, jlong g, jlong surface, jintArray pixels, jint translateX,
                                       jint translateY, jint clipX, jint clipY, jint clipWidth, jint clipHeight,
                                       jboolean depth, jint hints) {
    guard(env, [&] {
        m3g::Graphics* s = surfaceOf(surface);
        // The target's pixels, translation and clip, as the Java side read them.
        std::span<std::uint32_t> dst = s->pixels();
        if (env->GetArrayLength(pixels) != static_cast<jsize>(dst.size()))
            throw m3g::IllegalArgumentException("Graphics3D.bindTarget: the adapter's pixel count does not match its size");
        env->GetIntArrayRegion(pixels, 0, static_cast<jsize>(dst.size()), reinterpret_cast<jint*>(dst.data()));
        s->translate(translateX - s->getTranslateX(), translateY - s->getTranslateY());
        s->setClip(clipX, clipY, clipWidth, clipHeight);
        g3d(g)->bindTarget(s, depth == JNI_TRUE, hints);
    });
}

M3G_JNI(void, Graphics3D, release)(JNIEnv* env, jclass, jlong g, jlong surface, jintArray pixels) {
    guard(env, [&] {
        g3d(g)->releaseTarget();
        if (surface) {
            std::span<const std::uint32_t> src = std::as_const(*surfaceOf(surface)).pixels();
            env->SetIntArrayRegion(pixels, 0, static_cast<jsize>(src.size()), reinterpret_cast<const jint*>(src.data()));
        }
    });
}

M3G_JNI(jint, Graphics3D, getHints)(JNIEnv* env, jclass, jlong g) {
    return guard(env, [&] { return g3d(g)->getHints(); });
}

M3G_JNI(jboolean, Graphics3D, isDepthBufferEnabled)(JNIEnv* env, jclass, jlong g) {
    return guard(env, [&] { return static_cast<jboolean>(g3d(g)->isDepthBufferEnabled()); });
}

G3D(setViewport)(JNIEnv* env, jclass, jlong g, jint x, jint y, jint w, jint h) {
    guard(env, [&] { g3d(g)->setViewport(x, y, w, h); });
}

M3G_JNI(jint, Graphics3D, viewport)(JNIEnv* env, jclass, jlong g, jint which) {
    return guard(env, [&] {
        const Graphics3D* p = g3d(g);
        const int v[4] = {p->getViewportX(), p->getViewportY(), p->getViewportWidth(), p->getViewportHeight()};
        return v[which & 3];
    });
}

G3D(setDepthRange)(JNIEnv* env, jclass, jlong g, jfloat near, jfloat far) {
    guard(env, [&] { g3d(g)->setDepthRange(near, far); });
}

M3G_JNI(jfloat, Graphics3D, depthRange)(JNIEnv* env, jclass, jlong g, jboolean far) {
    return guard(env, [&] { return far ? g3d(g)->getDepthRangeFar() : g3d(g)->getDepthRangeNear(); });
}

G3D(clear)(JNIEnv* env, jclass, jlong g, jobject background) {
    guard(env, [&] { g3d(g)->clear(arg<m3g::Background>(env, background)); });
}

G3D(renderWorld)(JNIEnv* env, jclass, jlong g, jobject world) {
    guard(env, [&] { g3d(g)->render(arg<m3g::World>(env, world)); });
}

G3D(renderNode)(JNIEnv* env, jclass, jlong g, jobject node, jobject transform) {
    guard(env, [&] {
        const OptionalTransform t(env, transform);
        g3d(g)->render(arg<m3g::Node>(env, node), t.get());
    });
}

G3D(renderImmediate)(JNIEnv* env, jclass, jlong g, jobject vertices, jobject triangles, jobject appearance,
                     jobject transform, jint scope) {
    guard(env, [&] {
        const OptionalTransform t(env, transform);
        g3d(g)->render(arg<m3g::VertexBuffer>(env, vertices), arg<m3g::IndexBuffer>(env, triangles),
                       arg<m3g::Appearance>(env, appearance), t.get(), scope);
    });
}

G3D(setCamera)(JNIEnv* env, jclass, jlong g, jobject camera, jobject transform) {
    guard(env, [&] {
        const OptionalTransform t(env, transform);
        g3d(g)->setCamera(arg<m3g::Camera>(env, camera), t.get());
    });
}

M3G_JNI(jobject, Graphics3D, getCamera)(JNIEnv* env, jclass, jlong g, jobject transform) {
    return guard(env, [&] {
        m3g::Transform t;
        m3g::Ref<m3g::Camera> camera = g3d(g)->getCamera(transform ? &t : nullptr);
        if (transform) store(env, transform, t);
        return peer(env, camera);
    });
}

M3G_JNI(jint, Graphics3D, addLight)(JNIEnv* env, jclass, jlong g, jobject light, jobject transform) {
    return guard(env, [&] {
        const OptionalTransform t(env, transform);
        return g3d(g)->addLight(arg<m3g::Light>(env, light), t.get());
    });
}

G3D(setLight)(JNIEnv* env, jclass, jlong g, jint index, jobject light, jobject transform) {
    guard(env, [&] {
        const OptionalTransform t(env, transform);
        g3d(g)->setLight(index, arg<m3g::Light>(env, light), t.get());
    });
}

G3D(resetLights)(JNIEnv* env, jclass, jlong g) {
    guard(env, [&] { g3d(g)->resetLights(); });
}

M3G_JNI(jint, Graphics3D, getLightCount)(JNIEnv* env, jclass, jlong g) {
    return guard(env, [&] { return g3d(g)->getLightCount(); });
}

M3G_JNI(jobject, Graphics3D, getLight)(JNIEnv* env, jclass, jlong g, jint index, jobject transform) {
    return guard(env, [&] {
        m3g::Transform t;
        m3g::Ref<m3g::Light> light = g3d(g)->getLight(index, transform ? &t : nullptr);
        if (transform) store(env, transform, t);
        return peer(env, light);
    });
}
