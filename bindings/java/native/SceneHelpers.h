// Helpers of the scene-graph and animation classes' native methods
// (Transformable, Node, Group, Camera, KeyframeSequence, RayIntersection).
//
// m3g-vk tells a Java null array from a present one by the span's data
// pointer (a null data() is null). A copy of a zero-length Java array is an
// empty std::vector, whose data() may be null too, so a present but empty
// array would read as null (NullPointerException instead of the
// IllegalArgumentException for a short array): nonNull() keeps it present.
#pragma once

#include <jni.h>

#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include <m3g/RayIntersection.h>

#include "Arrays.h"

namespace m3gjni {

/// `s`, or an empty span with a non-null data pointer where `s` has none.
template <class T>
std::span<T> nonNull(std::span<T> s) noexcept {
    if (s.data() != nullptr) return s;
    static std::remove_const_t<T> none[1]{};
    return std::span<T>(none, 0);
}

/// A Java float[] argument that may be null: its copy (a span with null data
/// for null, a present span otherwise, even when empty).
class FloatsInOrNull {
public:
    FloatsInOrNull(JNIEnv* env, jfloatArray array, const char* where) {
        if (array) values_ = copyIn(env, array, where);
    }
    std::span<const float> span() const noexcept {
        if (!values_) return {};
        return nonNull(std::span<const float>(*values_));
    }

private:
    std::optional<std::vector<float>> values_;
};

/// A float[] the call writes into, which may be null (null data then);
/// starts with the array's values, so elements the call leaves alone keep
/// theirs. commit() after the call succeeded.
class FloatsOutOrNull {
public:
    FloatsOutOrNull(JNIEnv* env, jfloatArray array, const char* where) {
        if (array) out_.emplace(env, array, where);
    }
    std::span<float> span() noexcept {
        if (!out_) return {};
        return nonNull(out_->span());
    }
    void commit() {
        if (out_) out_->commit();
    }

private:
    std::optional<FloatsOut> out_;
};

/// A float[] the call writes into (NullPointerException naming `where` for
/// null), present even when empty; starts with the array's values.
class FloatsInOut {
public:
    FloatsInOut(JNIEnv* env, jfloatArray array, const char* where) : out_(env, array, where) {}
    std::span<float> span() noexcept { return nonNull(out_.span()); }
    void commit() { out_.commit(); }

private:
    FloatsOut out_;
};

/// RayIntersection (RayIntersection.cpp): the native result behind a Java
/// RayIntersection (its `handle` field). It never holds the intersected
/// node; the Java object does (its `intersected` field), so the native
/// result can be freed on the Cleaner's thread.
m3g::RayIntersection* rayIntersectionOf(JNIEnv* env, jobject ri);
/// Stores a pick's result in a Java RayIntersection: the intersected node
/// as its peer, the rest natively.
void storePick(JNIEnv* env, jobject ri, const m3g::RayIntersection& result);

}  // namespace m3gjni
