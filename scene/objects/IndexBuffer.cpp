#include <m3g/IndexBuffer.h>

#include <algorithm>

#include "Check.h"

namespace m3g {

IndexBuffer::IndexBuffer() = default;

IndexBuffer::IndexBuffer(const IndexBuffer& other) = default;

IndexBuffer::~IndexBuffer() = default;

void IndexBuffer::getIndices(std::span<int> indices) const {
    detail::requireArray(indices, triangles_.size(), "IndexBuffer::getIndices", "indices");
    std::copy(triangles_.begin(), triangles_.end(), indices.begin());
}

void IndexBuffer::setTriangles(std::vector<int> triangles) {
    triangles_ = std::move(triangles);
    maxIndex_ = triangles_.empty() ? -1 : *std::max_element(triangles_.begin(), triangles_.end());
    touch();
}

}  // namespace m3g
