// javax.microedition.m3g.TriangleStripArray's native methods (JSR-184 1.1,
// TriangleStripArray; getIndexCount and getIndices are IndexBuffer's, whose
// Java declarations are abstract and implemented here).
#include <m3g/IndexBuffer.h>
#include <m3g/TriangleStripArray.h>

#include "Arrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::IndexBuffer;
using m3g::TriangleStripArray;

M3G_JNI(jlong, TriangleStripArray, createImplicit)(JNIEnv* env, jclass, jint firstIndex, jintArray stripLengths) {
    return guard(env, [&] {
        SpanIn<jintArray> lengths(env, stripLengths);
        return handleOf(m3g::make<TriangleStripArray>(firstIndex, lengths.span()));
    });
}

M3G_JNI(jlong, TriangleStripArray, createExplicit)(JNIEnv* env, jclass, jintArray indices, jintArray stripLengths) {
    return guard(env, [&] {
        SpanIn<jintArray> in(env, indices);
        SpanIn<jintArray> lengths(env, stripLengths);
        return handleOf(m3g::make<TriangleStripArray>(in.span(), lengths.span()));
    });
}

M3G_JNI(jint, TriangleStripArray, getIndexCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<IndexBuffer>(env, thiz)->getIndexCount(); });
}

M3G_JNI(void, TriangleStripArray, getIndices)(JNIEnv* env, jobject thiz, jintArray indices) {
    guard(env, [&] {
        const IndexBuffer* ib = self<IndexBuffer>(env, thiz);
        const auto n = static_cast<std::size_t>(ib->getIndexCount());
        SpanOut<jintArray> out(env, indices, n);
        ib->getIndices(out.span());
        out.commit(n);
    });
}
