// javax.microedition.m3g.VertexArray's native methods (JSR-184 1.1, VertexArray).
#include <m3g/VertexArray.h>

#include "Arrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::VertexArray;

namespace {
// The values set() reads or get() writes: numVertices * componentCount (the
// copy limit; the C++ API checks the range and the length).
std::size_t valuesFor(const VertexArray* a, jint numVertices) {
    return elementsFor({numVertices, a->getComponentCount()});
}

template <class J>
void setValues(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices, J values) {
    guard(env, [&] {
        VertexArray* a = self<VertexArray>(env, thiz);
        SpanIn<J> in(env, values, valuesFor(a, numVertices));
        a->set(firstVertex, numVertices, in.span());
    });
}

template <class J>
void getValues(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices, J values) {
    guard(env, [&] {
        const VertexArray* a = self<VertexArray>(env, thiz);
        const std::size_t n = valuesFor(a, numVertices);
        SpanOut<J> out(env, values, n);
        a->get(firstVertex, numVertices, out.span());
        out.commit(n);
    });
}
}  // namespace

M3G_JNI(jlong, VertexArray, create)(JNIEnv* env, jclass, jint numVertices, jint numComponents, jint componentSize) {
    return guard(env, [&] { return handleOf(m3g::make<VertexArray>(numVertices, numComponents, componentSize)); });
}

M3G_JNI(void, VertexArray, setBytes)(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices, jbyteArray values) {
    setValues(env, thiz, firstVertex, numVertices, values);
}
M3G_JNI(void, VertexArray, setShorts)(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices,
                                      jshortArray values) {
    setValues(env, thiz, firstVertex, numVertices, values);
}
M3G_JNI(void, VertexArray, getBytes)(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices, jbyteArray values) {
    getValues(env, thiz, firstVertex, numVertices, values);
}
M3G_JNI(void, VertexArray, getShorts)(JNIEnv* env, jobject thiz, jint firstVertex, jint numVertices,
                                      jshortArray values) {
    getValues(env, thiz, firstVertex, numVertices, values);
}

M3G_JNI(jint, VertexArray, getComponentCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<VertexArray>(env, thiz)->getComponentCount(); });
}
M3G_JNI(jint, VertexArray, getComponentType)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<VertexArray>(env, thiz)->getComponentType(); });
}
M3G_JNI(jint, VertexArray, getVertexCount)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<VertexArray>(env, thiz)->getVertexCount(); });
}
