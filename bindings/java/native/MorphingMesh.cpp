// javax.microedition.m3g.MorphingMesh's native methods (JSR-184 1.1, MorphingMesh).
#include <m3g/Appearance.h>
#include <m3g/IndexBuffer.h>
#include <m3g/MorphingMesh.h>
#include <m3g/VertexBuffer.h>

#include "ObjectArrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::Appearance;
using m3g::IndexBuffer;
using m3g::MorphingMesh;
using m3g::VertexBuffer;

M3G_JNI(jlong, MorphingMesh, create)(JNIEnv* env, jclass, jobject base, jobjectArray targets, jobject submesh,
                                     jobject appearance) {
    return guard(env, [&] {
        RefsIn<VertexBuffer> t(env, targets);
        return handleOf(m3g::make<MorphingMesh>(arg<VertexBuffer>(env, base), t.span(),
                                                arg<IndexBuffer>(env, submesh), arg<Appearance>(env, appearance)));
    });
}

M3G_JNI(jlong, MorphingMesh, createSubmeshes)(JNIEnv* env, jclass, jobject base, jobjectArray targets,
                                              jobjectArray submeshes, jobjectArray appearances) {
    return guard(env, [&] {
        RefsIn<VertexBuffer> t(env, targets);
        RefsIn<IndexBuffer> s(env, submeshes);
        RefsIn<Appearance> a(env, appearances);
        return handleOf(m3g::make<MorphingMesh>(arg<VertexBuffer>(env, base), t.span(), s.span(), a.span()));
    });
}

M3G_JNI(jobject, MorphingMesh, getMorphTarget)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<MorphingMesh>(env, thiz)->getMorphTarget(index)); });
}

M3G_JNI(jint, MorphingMesh, getMorphTargetCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<MorphingMesh>(env, thiz)->getMorphTargetCount(); });
}

M3G_JNI(void, MorphingMesh, setWeights)(JNIEnv* env, jobject thiz, jfloatArray weights) {
    guard(env, [&] {
        MorphingMesh* mesh = self<MorphingMesh>(env, thiz);
        SpanIn<jfloatArray> in(env, weights, static_cast<std::size_t>(mesh->getMorphTargetCount()));
        mesh->setWeights(in.span());
    });
}

M3G_JNI(void, MorphingMesh, getWeights)(JNIEnv* env, jobject thiz, jfloatArray weights) {
    guard(env, [&] {
        const MorphingMesh* mesh = self<MorphingMesh>(env, thiz);
        const auto n = static_cast<std::size_t>(mesh->getMorphTargetCount());
        SpanOut<jfloatArray> out(env, weights, n);
        mesh->getWeights(out.span());
        out.commit(n);
    });
}
