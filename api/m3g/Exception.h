// The Java exception family of JSR-184, under one base (JSR-184 1.1, package overview).
//
// Messages name the class, the method and the valid range, e.g.
// "Light::setSpotAngle: angle 95 out of range [0, 90]".
#pragma once

#include <m3g/Export.h>

#include <stdexcept>
#include <string>

namespace m3g {

/// Base of every exception thrown at the M3G API boundary.
class M3G_API Exception : public std::runtime_error {
public:
    explicit Exception(const std::string& what) : std::runtime_error(what) {}
};

/// A required object reference was null.
class M3G_API NullPointerException : public Exception {
public:
    explicit NullPointerException(const std::string& what) : Exception(what) {}
};

/// An argument value, enum or object is not acceptable (INVALID_VALUE/ENUM/OBJECT).
class M3G_API IllegalArgumentException : public Exception {
public:
    explicit IllegalArgumentException(const std::string& what) : Exception(what) {}
};

/// The call is not allowed in the object's current state (INVALID_OPERATION).
class M3G_API IllegalStateException : public Exception {
public:
    explicit IllegalStateException(const std::string& what) : Exception(what) {}
};

/// An index is outside its valid range (INVALID_INDEX).
class M3G_API IndexOutOfBoundsException : public Exception {
public:
    explicit IndexOutOfBoundsException(const std::string& what) : Exception(what) {}
};

/// A matrix that must be inverted is singular, or a projection is degenerate.
class M3G_API ArithmeticException : public Exception {
public:
    explicit ArithmeticException(const std::string& what) : Exception(what) {}
};

/// A file or stream could not be read or is not a valid M3G file (java.io.IOException).
class M3G_API IOException : public Exception {
public:
    explicit IOException(const std::string& what) : Exception(what) {}
};

/// Allocation failed or a size exceeds what the implementation can hold.
class M3G_API OutOfMemoryError : public Exception {
public:
    explicit OutOfMemoryError(const std::string& what) : Exception(what) {}
};

}  // namespace m3g
