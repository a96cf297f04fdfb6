// Java arrays in and out of native calls: always copies (JSR-184 1.1 methods
// copy their array arguments), never pinned across m3g-vk calls. A null
// array is a NullPointerException naming the method, as the specification
// lists for every array argument.
#pragma once

#include <jni.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <m3g/Exception.h>

namespace m3gjni {

template <class J>
struct ArrayTraits;
template <>
struct ArrayTraits<jfloatArray> {
    using Element = float;
    static void get(JNIEnv* e, jfloatArray a, jsize n, float* p) { e->GetFloatArrayRegion(a, 0, n, p); }
    static void set(JNIEnv* e, jfloatArray a, jsize n, const float* p) { e->SetFloatArrayRegion(a, 0, n, p); }
};
template <>
struct ArrayTraits<jintArray> {
    using Element = std::int32_t;
    static void get(JNIEnv* e, jintArray a, jsize n, std::int32_t* p) { e->GetIntArrayRegion(a, 0, n, reinterpret_cast<jint*>(p)); }
    static void set(JNIEnv* e, jintArray a, jsize n, const std::int32_t* p) {
        e->SetIntArrayRegion(a, 0, n, reinterpret_cast<const jint*>(p));
    }
};
template <>
struct ArrayTraits<jshortArray> {
    using Element = std::int16_t;
    static void get(JNIEnv* e, jshortArray a, jsize n, std::int16_t* p) { e->GetShortArrayRegion(a, 0, n, p); }
    static void set(JNIEnv* e, jshortArray a, jsize n, const std::int16_t* p) { e->SetShortArrayRegion(a, 0, n, p); }
};
template <>
struct ArrayTraits<jbyteArray> {
    using Element = std::int8_t;
    static void get(JNIEnv* e, jbyteArray a, jsize n, std::int8_t* p) {
        e->GetByteArrayRegion(a, 0, n, reinterpret_cast<jbyte*>(p));
    }
    static void set(JNIEnv* e, jbyteArray a, jsize n, const std::int8_t* p) {
        e->SetByteArrayRegion(a, 0, n, reinterpret_cast<const jbyte*>(p));
    }
};

/// NullPointerException "<where>: the array is null" for a null array.
inline void requireArray(jarray array, const char* where) {
    if (!array) throw m3g::NullPointerException(std::string(where) + ": the array is null");
}

/// A copy of a whole Java array (NPE for null).
template <class J>
std::vector<typename ArrayTraits<J>::Element> copyIn(JNIEnv* env, J array, const char* where) {
    requireArray(array, where);
    std::vector<typename ArrayTraits<J>::Element> out;
    // A zero-length Java array must stay non-null for m3g-vk (whose span
    // with a null data() means a Java null): capacity first.
    out.reserve(1);
    out.resize(static_cast<std::size_t>(env->GetArrayLength(array)));
    ArrayTraits<J>::get(env, array, static_cast<jsize>(out.size()), out.data());
    return out;
}
inline std::vector<float> floatsIn(JNIEnv* env, jfloatArray array, const char* where = "m3g") {
    return copyIn(env, array, where);
}

/// A native copy of a Java array that the call writes into, copied back by
/// commit() (after the call succeeded). NPE for null. It starts with the
/// array's values, so elements the call does not write come back unchanged.
template <class J>
class ArrayOut {
public:
    ArrayOut(JNIEnv* env, J array, const char* where) : env_(env), array_(array) {
        requireArray(array, where);
        data_.reserve(1);  // non-null data() for a zero-length array (see copyIn)
        data_.resize(static_cast<std::size_t>(env->GetArrayLength(array)));
        ArrayTraits<J>::get(env, array, static_cast<jsize>(data_.size()), data_.data());
    }
    std::span<typename ArrayTraits<J>::Element> span() noexcept { return data_; }
    void commit() { ArrayTraits<J>::set(env_, array_, static_cast<jsize>(data_.size()), data_.data()); }

private:
    JNIEnv* env_;
    J array_;
    std::vector<typename ArrayTraits<J>::Element> data_;
};
using FloatsOut = ArrayOut<jfloatArray>;

}  // namespace m3gjni
