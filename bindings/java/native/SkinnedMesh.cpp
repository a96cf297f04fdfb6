// javax.microedition.m3g.SkinnedMesh's native methods (JSR-184 1.1, SkinnedMesh).
#include <m3g/Appearance.h>
#include <m3g/Group.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Node.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Transform.h>
#include <m3g/VertexBuffer.h>

#include "ObjectArrays.h"
#include "Jni.h"
#include "Transforms.h"

using namespace m3gjni;
using m3g::Appearance;
using m3g::Group;
using m3g::IndexBuffer;
using m3g::Node;
using m3g::SkinnedMesh;
using m3g::VertexBuffer;

M3G_JNI(jlong, SkinnedMesh, create)(JNIEnv* env, jclass, jobject vertices, jobject submesh, jobject appearance,
                                    jobject skeleton) {
    return guard(env, [&] {
        return handleOf(m3g::make<SkinnedMesh>(arg<VertexBuffer>(env, vertices), arg<IndexBuffer>(env, submesh),
                                               arg<Appearance>(env, appearance), arg<Group>(env, skeleton)));
    });
}

M3G_JNI(jlong, SkinnedMesh, createSubmeshes)(JNIEnv* env, jclass, jobject vertices, jobjectArray submeshes,
                                             jobjectArray appearances, jobject skeleton) {
    return guard(env, [&] {
        RefsIn<IndexBuffer> s(env, submeshes);
        RefsIn<Appearance> a(env, appearances);
        return handleOf(
            m3g::make<SkinnedMesh>(arg<VertexBuffer>(env, vertices), s.span(), a.span(), arg<Group>(env, skeleton)));
    });
}

M3G_JNI(void, SkinnedMesh, addTransform)(JNIEnv* env, jobject thiz, jobject bone, jint weight, jint firstVertex,
                                         jint numVertices) {
    guard(env, [&] {
        self<SkinnedMesh>(env, thiz)->addTransform(arg<Node>(env, bone), weight, firstVertex, numVertices);
    });
}

M3G_JNI(jobject, SkinnedMesh, getSkeleton)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<SkinnedMesh>(env, thiz)->getSkeleton()); });
}

// The Java Transform is read first: a bone that was never added leaves it
// as it was (the C++ API does not touch it), and storing it back is then a
// no-op. Null stays null (the C++ API's NullPointerException).
M3G_JNI(void, SkinnedMesh, getBoneTransform)(JNIEnv* env, jobject thiz, jobject bone, jobject transform) {
    guard(env, [&] {
        const SkinnedMesh* mesh = self<SkinnedMesh>(env, thiz);
        m3g::Transform t;
        const bool present = transformOf(env, transform, t);
        mesh->getBoneTransform(arg<Node>(env, bone), present ? &t : nullptr);
        if (present) store(env, transform, t);
    });
}

// Either array may be null (only the count is wanted then).
M3G_JNI(jint, SkinnedMesh, getBoneVertices)(JNIEnv* env, jobject thiz, jobject bone, jintArray indices,
                                            jfloatArray weights) {
    return guard(env, [&] {
        const SkinnedMesh* mesh = self<SkinnedMesh>(env, thiz);
        Node* node = arg<Node>(env, bone);
        // The count first, so that the copies are no longer than it.
        const int n = mesh->getBoneVertices(node);
        const auto count = static_cast<std::size_t>(n);
        SpanOut<jintArray> outIndices(env, indices, count);
        SpanOut<jfloatArray> outWeights(env, weights, count);
        mesh->getBoneVertices(node, outIndices.span(), outWeights.span());
        outIndices.commit(count);
        outWeights.commit(count);
        return static_cast<jint>(n);
    });
}
