#include <m3g/TriangleStripArray.h>

#include "Check.h"

namespace m3g {

namespace {

// Validates the strip lengths (NPE, IAE) and returns their sum.
long long checkLengths(std::span<const int> stripLengths, const char* where) {
    if (stripLengths.data() == nullptr) detail::throwNull(where, "stripLengths");
    if (stripLengths.empty()) detail::throwIAE(detail::str(where, ": stripLengths is empty"));
    long long sum = 0;
    for (std::size_t i = 0; i < stripLengths.size(); ++i) {
        if (stripLengths[i] < 3)
            detail::throwIAE(detail::str(where, ": stripLengths[", i, "] = ", stripLengths[i], " is less than 3"));
        sum += stripLengths[i];
    }
    return sum;
}

}  // namespace

TriangleStripArray::TriangleStripArray(int firstIndex, std::span<const int> stripLengths) {
    const char* where = "TriangleStripArray::TriangleStripArray";
    const long long sum = checkLengths(stripLengths, where);
    if (firstIndex < 0 || firstIndex + sum > 65535)
        throw IndexOutOfBoundsException(detail::str(where, ": implicit indices [", firstIndex, ", ",
                                                    firstIndex + sum, ") out of range [0, 65535]"));
    stripLengths_.assign(stripLengths.begin(), stripLengths.end());
    stripIndices_.resize(static_cast<std::size_t>(sum));
    for (std::size_t i = 0; i < stripIndices_.size(); ++i) stripIndices_[i] = firstIndex + static_cast<int>(i);
    build();
}

TriangleStripArray::TriangleStripArray(std::span<const int> indices, std::span<const int> stripLengths) {
    const char* where = "TriangleStripArray::TriangleStripArray";
    if (indices.data() == nullptr) detail::throwNull(where, "indices");
    const long long sum = checkLengths(stripLengths, where);
    if (static_cast<long long>(indices.size()) < sum)
        detail::throwIAE(detail::str(where, ": indices has length ", indices.size(), ", the strips need ", sum));
    for (long long i = 0; i < sum; ++i)
        if (indices[i] < 0 || indices[i] > 65535)
            throw IndexOutOfBoundsException(
                detail::str(where, ": indices[", i, "] = ", indices[i], " out of range [0, 65535]"));
    stripLengths_.assign(stripLengths.begin(), stripLengths.end());
    stripIndices_.assign(indices.begin(), indices.begin() + sum);
    build();
}

TriangleStripArray::TriangleStripArray(const TriangleStripArray& other) = default;

TriangleStripArray::~TriangleStripArray() = default;

Object3D* TriangleStripArray::duplicateImpl(DuplicateMap&) const { return new TriangleStripArray(*this); }

void TriangleStripArray::build() {
    std::vector<int> tris;
    std::size_t count = 0;
    for (int len : stripLengths_) count += static_cast<std::size_t>(len - 2) * 3;
    tris.reserve(count);
    std::size_t start = 0;
    for (int len : stripLengths_) {
        const int* s = stripIndices_.data() + start;
        for (int j = 0; j + 2 < len; ++j) {
            tris.push_back(s[j]);
            if (j % 2 == 0) {
                tris.push_back(s[j + 1]);
                tris.push_back(s[j + 2]);
            } else {
                tris.push_back(s[j + 2]);
                tris.push_back(s[j + 1]);
            }
        }
        start += static_cast<std::size_t>(len);
    }
    setTriangles(std::move(tris));
}

}  // namespace m3g
