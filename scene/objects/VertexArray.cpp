#include <m3g/VertexArray.h>

#include <algorithm>

#include <m3g/Transform.h>

#include "Check.h"

namespace m3g {

VertexArray::VertexArray(int numVertices, int numComponents, int componentSize)
    : vertices_(numVertices), components_(numComponents), componentSize_(componentSize) {
    detail::requireRange(numVertices, 1, 65535, "VertexArray::VertexArray", "numVertices");
    detail::requireRange(numComponents, 2, 4, "VertexArray::VertexArray", "numComponents");
    detail::requireEnum(componentSize, {1, 2}, "VertexArray::VertexArray", "componentSize");
    const std::size_t n = static_cast<std::size_t>(numVertices) * numComponents;
    if (componentSize == 1)
        bytes_.assign(n, 0);
    else
        shorts_.assign(n, 0);
}

VertexArray::VertexArray(const VertexArray& other) = default;

VertexArray::~VertexArray() = default;

Object3D* VertexArray::duplicateImpl(DuplicateMap&) const { return new VertexArray(*this); }

void VertexArray::checkAccess(const char* where, int componentSize, int first, int count, std::size_t length,
                              bool isNull) const {
    if (isNull) detail::throwNull(where, "values");
    if (componentSize != componentSize_)
        detail::throwISE(detail::str(where, ": the array has component size ", componentSize_, ", this method needs ",
                                     componentSize));
    if (count < 0) detail::throwIAE(detail::str(where, ": numVertices ", count, " is negative"));
    if (first < 0 || static_cast<long long>(first) + count > vertices_)
        throw IndexOutOfBoundsException(detail::str(where, ": vertices [", first, ", ",
                                                    static_cast<long long>(first) + count,
                                                    ") out of range [0, ", vertices_, ")"));
    const std::size_t needed = static_cast<std::size_t>(count) * components_;
    if (length < needed)
        detail::throwIAE(detail::str(where, ": values has length ", length, ", needs at least ", needed));
}

void VertexArray::set(int firstVertex, int numVertices, std::span<const std::int8_t> values) {
    checkAccess("VertexArray::set", 1, firstVertex, numVertices, values.size(), values.data() == nullptr);
    const std::size_t n = static_cast<std::size_t>(numVertices) * components_;
    std::copy_n(values.begin(), n, bytes_.begin() + static_cast<std::ptrdiff_t>(firstVertex) * components_);
    touch();
}

void VertexArray::set(int firstVertex, int numVertices, std::span<const std::int16_t> values) {
    checkAccess("VertexArray::set", 2, firstVertex, numVertices, values.size(), values.data() == nullptr);
    const std::size_t n = static_cast<std::size_t>(numVertices) * components_;
    std::copy_n(values.begin(), n, shorts_.begin() + static_cast<std::ptrdiff_t>(firstVertex) * components_);
    touch();
}

void VertexArray::get(int firstVertex, int numVertices, std::span<std::int8_t> values) const {
    checkAccess("VertexArray::get", 1, firstVertex, numVertices, values.size(), values.data() == nullptr);
    const std::size_t n = static_cast<std::size_t>(numVertices) * components_;
    std::copy_n(bytes_.begin() + static_cast<std::ptrdiff_t>(firstVertex) * components_, n, values.begin());
}

void VertexArray::get(int firstVertex, int numVertices, std::span<std::int16_t> values) const {
    checkAccess("VertexArray::get", 2, firstVertex, numVertices, values.size(), values.data() == nullptr);
    const std::size_t n = static_cast<std::size_t>(numVertices) * components_;
    std::copy_n(shorts_.begin() + static_cast<std::ptrdiff_t>(firstVertex) * components_, n, values.begin());
}

const void* VertexArray::data() const noexcept {
    return componentSize_ == 1 ? static_cast<const void*>(bytes_.data()) : static_cast<const void*>(shorts_.data());
}

void VertexArray::getFloats(int first, int count, std::span<float> out) const {
    const char* where = "VertexArray::getFloats";
    if (first < 0 || count < 0 || static_cast<long long>(first) + count > vertices_)
        throw IndexOutOfBoundsException(detail::str(where, ": vertices [", first, ", ",
                                                    static_cast<long long>(first) + count,
                                                    ") out of range [0, ", vertices_, ")"));
    const std::size_t n = static_cast<std::size_t>(count) * components_;
    detail::requireArray(out, n, where, "out");
    const std::size_t base = static_cast<std::size_t>(first) * components_;
    for (std::size_t i = 0; i < n; ++i)
        out[i] = componentSize_ == 1 ? static_cast<float>(bytes_[base + i]) : static_cast<float>(shorts_[base + i]);
}

// Declared in Transform.h; defined here because it needs the array layout.
void Transform::transform(const VertexArray* in, std::span<float> out, bool W) const {
    const char* where = "Transform::transform";
    detail::requireNonNull(in, where, "in");
    if (out.data() == nullptr) detail::throwNull(where, "out");
    const int comps = in->getComponentCount();
    if (comps == 4)
        detail::throwIAE(detail::str(where, ": the VertexArray has 4 components (only 2 or 3 can be transformed)"));
    const int count = in->getVertexCount();
    const std::size_t needed = static_cast<std::size_t>(count) * 4;
    if (out.size() < needed)
        detail::throwIAE(detail::str(where, ": out has length ", out.size(), ", needs at least ", needed));
    const float w = W ? 1.0f : 0.0f;
    for (int v = 0; v < count; ++v) {
        const float x = static_cast<float>(in->value(v, 0));
        const float y = static_cast<float>(in->value(v, 1));
        const float z = comps == 3 ? static_cast<float>(in->value(v, 2)) : 0.0f;
        float* o = out.data() + static_cast<std::size_t>(v) * 4;
        for (int r = 0; r < 4; ++r) o[r] = at(r, 0) * x + at(r, 1) * y + at(r, 2) * z + at(r, 3) * w;
    }
}

}  // namespace m3g
