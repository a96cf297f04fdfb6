// javax.microedition.m3g.VertexBuffer's native methods (JSR-184 1.1, VertexBuffer).
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include "Arrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::VertexArray;
using m3g::VertexBuffer;

M3G_JNI(jlong, VertexBuffer, create)(JNIEnv* env, jclass) {
    return guard(env, [] { return handleOf(m3g::make<VertexBuffer>()); });
}

M3G_JNI(jint, VertexBuffer, getVertexCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<VertexBuffer>(env, thiz)->getVertexCount(); });
}

// A bias is 3 (positions) or at most 3 (texture coordinates) floats; a null
// bias means zeros; a shorter one is the C++ API's IllegalArgumentException.
M3G_JNI(void, VertexBuffer, setPositions)(JNIEnv* env, jobject thiz, jobject positions, jfloat scale,
                                          jfloatArray bias) {
    guard(env, [&] {
        VertexBuffer* vb = self<VertexBuffer>(env, thiz);
        SpanIn<jfloatArray> b(env, bias, 3);
        vb->setPositions(arg<VertexArray>(env, positions), scale, b.span());
    });
}

M3G_JNI(void, VertexBuffer, setTexCoords)(JNIEnv* env, jobject thiz, jint index, jobject texCoords, jfloat scale,
                                          jfloatArray bias) {
    guard(env, [&] {
        VertexBuffer* vb = self<VertexBuffer>(env, thiz);
        SpanIn<jfloatArray> b(env, bias, 3);
        vb->setTexCoords(index, arg<VertexArray>(env, texCoords), scale, b.span());
    });
}

M3G_JNI(void, VertexBuffer, setNormals)(JNIEnv* env, jobject thiz, jobject normals) {
    guard(env, [&] { self<VertexBuffer>(env, thiz)->setNormals(arg<VertexArray>(env, normals)); });
}

M3G_JNI(void, VertexBuffer, setColors)(JNIEnv* env, jobject thiz, jobject colors) {
    guard(env, [&] { self<VertexBuffer>(env, thiz)->setColors(arg<VertexArray>(env, colors)); });
}

// scaleBias may be null; else it receives {scale, bx, by, bz}.
M3G_JNI(jobject, VertexBuffer, getPositions)(JNIEnv* env, jobject thiz, jfloatArray scaleBias) {
    return guard(env, [&] {
        const VertexBuffer* vb = self<VertexBuffer>(env, thiz);
        SpanOut<jfloatArray> out(env, scaleBias, 4);
        m3g::Ref<VertexArray> positions = vb->getPositions(out.span());
        out.commit(4);
        return peer(env, positions);
    });
}

// scaleBias may be null; else, when the unit has an array, it receives
// {scale, bs, bt[, br]}, and is left alone when the unit has none.
M3G_JNI(jobject, VertexBuffer, getTexCoords)(JNIEnv* env, jobject thiz, jint index, jfloatArray scaleBias) {
    return guard(env, [&] {
        const VertexBuffer* vb = self<VertexBuffer>(env, thiz);
        SpanOut<jfloatArray> out(env, scaleBias, 4);
        m3g::Ref<VertexArray> texCoords = vb->getTexCoords(index, out.span());
        if (texCoords) out.commit(static_cast<std::size_t>(texCoords->getComponentCount()) + 1);
        return peer(env, texCoords);
    });
}

M3G_JNI(jobject, VertexBuffer, getNormals)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<VertexBuffer>(env, thiz)->getNormals()); });
}

M3G_JNI(jobject, VertexBuffer, getColors)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return peer(env, self<VertexBuffer>(env, thiz)->getColors()); });
}

M3G_JNI(void, VertexBuffer, setDefaultColor)(JNIEnv* env, jobject thiz, jint argb) {
    guard(env, [&] { self<VertexBuffer>(env, thiz)->setDefaultColor(argb); });
}

M3G_JNI(jint, VertexBuffer, getDefaultColor)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<VertexBuffer>(env, thiz)->getDefaultColor(); });
}
