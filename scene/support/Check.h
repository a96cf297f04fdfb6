// Argument checks that throw the Java exceptions with messages naming the
// class, the method and the valid range ("Light::setSpotAngle: ...").
#pragma once

#include <initializer_list>
#include <span>
#include <sstream>
#include <string>

#include <m3g/Exception.h>

namespace m3g::detail {

template <class... Args>
std::string str(const Args&... args) {
    std::ostringstream os;
    (os << ... << args);
    return os.str();
}

[[noreturn]] inline void throwNull(const char* where, const char* what) {
    throw NullPointerException(str(where, ": ", what, " is null"));
}

template <class T>
inline void requireNonNull(const T* p, const char* where, const char* what) {
    if (!p) throwNull(where, what);
}

/// Java null array: a span with no data.
template <class T>
inline void requireArray(std::span<T> a, std::size_t minLength, const char* where, const char* what) {
    if (a.data() == nullptr) throwNull(where, what);
    if (a.size() < minLength)
        throw IllegalArgumentException(
            str(where, ": ", what, " has length ", a.size(), ", needs at least ", minLength));
}

inline void requireEnum(int v, std::initializer_list<int> valid, const char* where, const char* what) {
    for (int x : valid)
        if (x == v) return;
    std::ostringstream os;
    os << where << ": " << what << " " << v << " is not one of {";
    bool first = true;
    for (int x : valid) { os << (first ? "" : ", ") << x; first = false; }
    os << "}";
    throw IllegalArgumentException(os.str());
}

/// IAE unless lo <= v <= hi (NaN fails).
template <class T>
inline void requireRange(T v, T lo, T hi, const char* where, const char* what) {
    if (!(v >= lo && v <= hi))
        throw IllegalArgumentException(str(where, ": ", what, " ", v, " out of range [", lo, ", ", hi, "]"));
}

/// IOOBE unless 0 <= index < size.
inline void requireIndex(long long index, long long size, const char* where, const char* what) {
    if (index < 0 || index >= size)
        throw IndexOutOfBoundsException(str(where, ": ", what, " ", index, " out of range [0, ", size, ")"));
}

[[noreturn]] inline void throwIAE(const std::string& msg) { throw IllegalArgumentException(msg); }
[[noreturn]] inline void throwISE(const std::string& msg) { throw IllegalStateException(msg); }

}  // namespace m3g::detail
