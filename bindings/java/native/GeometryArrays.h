// Java arrays for the geometry and appearance classes (VertexArray,
// VertexBuffer, IndexBuffer, the meshes, Image2D): copies as in Arrays.h,
// with four differences that those methods need.
//   - A null Java array becomes a null span (data() == nullptr) and is passed
//     on: the C++ API then raises the spec's NullPointerException in the
//     order it documents, or reads null as "none" where JSR-184 allows it
//     (a bias, a scaleBias, the arrays of getBoneVertices, the appearances
//     of a Mesh).
//   - A non-null empty Java array becomes a non-null empty span: an empty
//     std::vector may have data() == nullptr, which the C++ API would take
//     for null (NPE where the spec wants IllegalArgumentException).
//   - A copy may be limited to the elements the call can use (`limit`): the
//     span is then min(length, limit) long, which passes or fails the C++
//     API's "array too short" check exactly as the whole array would, and a
//     small update from a large array does not copy all of it. Nothing is
//     read past the Java array's end: the copy is never longer than it.
//   - An output array is written back only as far as the call filled it
//     (commit(count)); JSR-184 leaves the rest of the caller's array as it was.
// Object arrays (IndexBuffer[], Appearance[], VertexBuffer[]) become
// std::vector<m3g::Ref<T>>, null elements kept null.
#pragma once

#include <jni.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include <m3g/Ref.h>

#include "Arrays.h"
#include "Jni.h"

namespace m3gjni {

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
/// elements, null kept null; commit(count) writes the first `count` back.
template <class J>
class SpanOut {
public:
    using Element = typename ArrayTraits<J>::Element;

    SpanOut(JNIEnv* env, J array, std::size_t limit = kWholeArray) : env_(env), array_(array) {
        if (!array_) return;
        data_.resize(std::min(static_cast<std::size_t>(env->GetArrayLength(array)), limit));
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

private:
    JNIEnv* env_;
    J array_;
    std::vector<Element> data_;
};

/// The native objects of a Java object array (T[] in Java, so every element
/// is a T), null elements kept null; a null array gives a null span.
template <class T>
class RefsIn {
public:
    RefsIn(JNIEnv* env, jobjectArray array) : null_(array == nullptr) {
        if (null_) return;
        const jsize n = env->GetArrayLength(array);
        refs_.reserve(static_cast<std::size_t>(n));
        for (jsize i = 0; i < n; ++i) {
            jobject element = env->GetObjectArrayElement(array, i);
            refs_.emplace_back(arg<T>(env, element));
            env->DeleteLocalRef(element);  // -Xcheck:jni: no local reference per element
        }
    }

    std::span<const m3g::Ref<T>> span() noexcept {
        if (null_) return {};
        return detail::nonNull<const m3g::Ref<T>>(refs_);
    }

private:
    bool null_;
    std::vector<m3g::Ref<T>> refs_;
};

}  // namespace m3gjni
