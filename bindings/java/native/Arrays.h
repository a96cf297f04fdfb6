// Java arrays in and out of native calls. JSR-184 1.1 methods copy their
// array arguments, so these always copy; nothing is pinned across an m3g-vk
// call.
//   - A null Java array becomes a null span (data() == nullptr) and is passed
//     on: the C++ API then raises the specification's NullPointerException in
//     the order it documents, or reads null as "none" where JSR-184 allows it
//     (a bias, a scaleBias, the value of getKeyframe, the arrays of
//     getBoneVertices, the appearances of a Mesh). Where the method itself
//     must refuse null first, requireArray() names it.
//   - A non-null empty Java array becomes a non-null empty span: an empty
//     std::vector may have data() == nullptr, which the C++ API would take
//     for null (NullPointerException where the specification wants
//     IllegalArgumentException for a short array).
//   - A copy may be limited to the elements the call can use (`limit`): the
//     span is then min(length, limit) long, which passes or fails the C++
//     API's "array too short" check exactly as the whole array would, and a
//     small update from a large array does not copy all of it. Nothing is
//     read past the Java array's end.
//   - An output array is written back only as far as the call filled it
//     (commit(count)), or whole where the call may leave elements alone
//     (Start::Values, then commit()): JSR-184 leaves the rest of the
//     caller's array as it was.
#pragma once

#include <jni.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
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

/// No limit: the whole array.
inline constexpr std::size_t kWholeArray = std::numeric_limits<std::size_t>::max();

/// The number of elements `factors` multiply to, as a copy limit: 0 if one is
/// negative (the C++ API rejects the call before it reads the array),
/// saturating instead of overflowing.
inline std::size_t elementsFor(std::initializer_list<long long> factors) noexcept {
    std::size_t n = 1;
    for (long long f : factors) {
        if (f <= 0) return 0;
        const auto u = static_cast<std::size_t>(f);
        if (n > kWholeArray / u) return kWholeArray;
        n *= u;
    }
    return n;
}

namespace detail {
/// A span over `v`, non-null even when `v` is empty.
template <class T>
std::span<T> nonNull(std::vector<std::remove_const_t<T>>& v) noexcept {
    static std::remove_const_t<T> none{};
    return v.empty() ? std::span<T>(&none, 0) : std::span<T>(v.data(), v.size());
}
}  // namespace detail

/// A copy of (the first `limit` elements of) a Java array, null kept null.
template <class J>
class SpanIn {
public:
    using Element = typename ArrayTraits<J>::Element;

    SpanIn(JNIEnv* env, J array, std::size_t limit = kWholeArray) : null_(array == nullptr) {
        if (null_) return;
        const auto length = static_cast<std::size_t>(env->GetArrayLength(array));
        data_.resize(std::min(length, limit));
        if (!data_.empty()) ArrayTraits<J>::get(env, array, static_cast<jsize>(data_.size()), data_.data());
    }

    std::span<const Element> span() noexcept {
        if (null_) return {};
        return detail::nonNull<const Element>(data_);
    }
    /// The same bytes as another element type of the same size (int8 -> uint8).
    template <class U>
    std::span<const U> as() noexcept {
        static_assert(sizeof(U) == sizeof(Element));
        const auto s = span();
        return {reinterpret_cast<const U*>(s.data()), s.size()};
    }

private:
    bool null_;
    std::vector<Element> data_;
};

/// A native buffer for a Java array that a call fills: min(length, limit)
/// elements, null kept null. It starts zeroed, or with the array's values
/// (Start::Values) where the call may leave elements alone.
template <class J>
class SpanOut {
public:
    using Element = typename ArrayTraits<J>::Element;
    enum class Start { Zeros, Values };

    SpanOut(JNIEnv* env, J array, std::size_t limit = kWholeArray, Start start = Start::Zeros)
        : env_(env), array_(array) {
        if (!array_) return;
        data_.resize(std::min(static_cast<std::size_t>(env->GetArrayLength(array)), limit));
        if (start == Start::Values && !data_.empty())
            ArrayTraits<J>::get(env, array, static_cast<jsize>(data_.size()), data_.data());
    }

    std::span<Element> span() noexcept {
        if (!array_) return {};
        return detail::nonNull<Element>(data_);
    }
    bool isNull() const noexcept { return array_ == nullptr; }
    /// Writes the first `count` elements (at most the buffer's) back; nothing for null.
    void commit(std::size_t count) {
        if (!array_) return;
        const std::size_t n = std::min(count, data_.size());
        if (n > 0) ArrayTraits<J>::set(env_, array_, static_cast<jsize>(n), data_.data());
    }
    /// Writes the whole buffer back.
    void commit() { commit(data_.size()); }

private:
    JNIEnv* env_;
    J array_;
    std::vector<Element> data_;
};

/// A float[] the call writes into and may leave partly alone
/// (NullPointerException naming `where` for null).
class FloatsInOut : public SpanOut<jfloatArray> {
public:
    FloatsInOut(JNIEnv* env, jfloatArray array, const char* where)
        : SpanOut(env, (requireArray(array, where), array), kWholeArray, Start::Values) {}
};

/// A copy of a whole Java array (NullPointerException naming `where` for null).
template <class J>
SpanIn<J> requiredIn(JNIEnv* env, J array, const char* where) {
    requireArray(array, where);
    return SpanIn<J>(env, array);
}

}  // namespace m3gjni
