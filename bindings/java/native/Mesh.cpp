// javax.microedition.m3g.Mesh's native methods (JSR-184 1.1, Mesh).
#include <m3g/Appearance.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Mesh.h>
#include <m3g/VertexBuffer.h>

#include "ObjectArrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::Appearance;
using m3g::IndexBuffer;
using m3g::Mesh;
using m3g::VertexBuffer;

M3G_JNI(jlong, Mesh, create)(JNIEnv* env, jclass, jobject vertices, jobject submesh, jobject appearance) {
    return guard(env, [&] {
        return handleOf(m3g::make<Mesh>(arg<VertexBuffer>(env, vertices), arg<IndexBuffer>(env, submesh),
                                        arg<Appearance>(env, appearance)));
    });
}

M3G_JNI(jlong, Mesh, createSubmeshes)(JNIEnv* env, jclass, jobject vertices, jobjectArray submeshes,
                                      jobjectArray appearances) {
    return guard(env, [&] {
        RefsIn<IndexBuffer> s(env, submeshes);
        RefsIn<Appearance> a(env, appearances);
        return handleOf(m3g::make<Mesh>(arg<VertexBuffer>(env, vertices), s.span(), a.span()));
    });
}

M3G_JNI(void, Mesh, setAppearance)(JNIEnv* env, jobject thiz, jint index, jobject appearance) {
    guard(env, [&] { self<Mesh>(env, thiz)->setAppearance(index, arg<Appearance>(env, appearance)); });
}

M3G_JNI(jobject, Mesh, getAppearance)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<Mesh>(env, thiz)->getAppearance(index)); });
}

M3G_JNI(jobject, Mesh, getIndexBuffer)(JNIEnv* env, jobject thiz, jint index) {
    return guard(env, [&] { return peer(env, self<Mesh>(env, thiz)->getIndexBuffer(index)); });
}

M3G_JNI(jobject, Mesh, getVertexBuffer)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<Mesh>(env, thiz)->getVertexBuffer()); });
}

M3G_JNI(jint, Mesh, getSubmeshCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Mesh>(env, thiz)->getSubmeshCount(); });
}
