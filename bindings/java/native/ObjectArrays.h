// Java object arrays (IndexBuffer[], Appearance[], VertexBuffer[]) for the
// mesh classes' native methods: the native objects, null elements kept null,
// a null array a null span (see Arrays.h for why an empty one is not).
#pragma once

#include <jni.h>

#include <span>
#include <vector>

#include <m3g/Ref.h>

#include "Arrays.h"
#include "Jni.h"

namespace m3gjni {

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
