#include <m3g/VertexBuffer.h>

#include <cmath>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

VertexBuffer::VertexBuffer() { texCoordScale_.fill(1.0f); }

VertexBuffer::VertexBuffer(const VertexBuffer& other) = default;

VertexBuffer::~VertexBuffer() = default;

Object3D* VertexBuffer::duplicateImpl(DuplicateMap&) const { return new VertexBuffer(*this); }

void VertexBuffer::collectReferences(std::vector<Object3D*>& out) const {
    Object3D::collectReferences(out);
    if (positions_) out.push_back(positions_.get());
    if (normals_) out.push_back(normals_.get());
    if (colors_) out.push_back(colors_.get());
    for (const auto& t : texCoords_)
        if (t) out.push_back(t.get());
}

void VertexBuffer::checkCount(const VertexArray* array, const VertexArray* current, const char* where) const {
    if (!array) return;
    const VertexArray* others[3 + kMaxTextureUnits] = {positions_.get(), normals_.get(), colors_.get()};
    for (int i = 0; i < kMaxTextureUnits; ++i) others[3 + i] = texCoords_[i].get();
    for (const VertexArray* o : others) {
        if (!o || o == current) continue;
        if (o->getVertexCount() != array->getVertexCount())
            detail::throwIAE(detail::str(where, ": the array has ", array->getVertexCount(),
                                         " vertices, the other arrays of the buffer have ", o->getVertexCount()));
    }
}

void VertexBuffer::updateCount() noexcept {
    vertexCount_ = 0;
    const VertexArray* all[3 + kMaxTextureUnits] = {positions_.get(), normals_.get(), colors_.get()};
    for (int i = 0; i < kMaxTextureUnits; ++i) all[3 + i] = texCoords_[i].get();
    for (const VertexArray* a : all)
        if (a) {
            vertexCount_ = a->getVertexCount();
            return;
        }
}

void VertexBuffer::setPositions(VertexArray* positions, float scale, std::span<const float> bias) {
    const char* where = "VertexBuffer::setPositions";
    if (positions) {
        if (positions->getComponentCount() != 3)
            detail::throwIAE(detail::str(where, ": positions has ", positions->getComponentCount(),
                                         " components, needs 3"));
        if (bias.data() && bias.size() < 3)
            detail::throwIAE(detail::str(where, ": bias has length ", bias.size(), ", needs at least 3"));
        checkCount(positions, positions_.get(), where);
    }
    positions_ = positions;
    positionScale_ = scale;
    if (positions && bias.data())
        positionBias_ = {bias[0], bias[1], bias[2]};
    else
        positionBias_ = {0, 0, 0};
    updateCount();
    touch();
}

void VertexBuffer::setTexCoords(int index, VertexArray* texCoords, float scale, std::span<const float> bias) {
    const char* where = "VertexBuffer::setTexCoords";
    detail::requireIndex(index, getLimits().numTextureUnits, where, "index");
    if (texCoords) {
        const int comps = texCoords->getComponentCount();
        if (comps != 2 && comps != 3)
            detail::throwIAE(detail::str(where, ": texCoords has ", comps, " components, needs 2 or 3"));
        if (bias.data() && bias.size() < static_cast<std::size_t>(comps))
            detail::throwIAE(detail::str(where, ": bias has length ", bias.size(), ", needs at least ", comps));
        checkCount(texCoords, texCoords_[index].get(), where);
    }
    texCoords_[index] = texCoords;
    texCoordScale_[index] = scale;
    texCoordBias_[index] = {0, 0, 0};
    if (texCoords && bias.data())
        for (int i = 0; i < texCoords->getComponentCount(); ++i) texCoordBias_[index][i] = bias[i];
    updateCount();
    touch();
}

void VertexBuffer::setNormals(VertexArray* normals) {
    const char* where = "VertexBuffer::setNormals";
    if (normals) {
        if (normals->getComponentCount() != 3)
            detail::throwIAE(detail::str(where, ": normals has ", normals->getComponentCount(), " components, needs 3"));
        checkCount(normals, normals_.get(), where);
    }
    normals_ = normals;
    updateCount();
    touch();
}

void VertexBuffer::setColors(VertexArray* colors) {
    const char* where = "VertexBuffer::setColors";
    if (colors) {
        if (colors->getComponentType() != 1)
            detail::throwIAE(detail::str(where, ": colors must be a byte array (component size is ",
                                         colors->getComponentType(), ")"));
        const int comps = colors->getComponentCount();
        if (comps != 3 && comps != 4)
            detail::throwIAE(detail::str(where, ": colors has ", comps, " components, needs 3 or 4"));
        checkCount(colors, colors_.get(), where);
    }
    colors_ = colors;
    updateCount();
    touch();
}

Ref<VertexArray> VertexBuffer::getPositions(std::span<float> scaleBias) const {
    if (scaleBias.data()) {
        if (scaleBias.size() < 4)
            detail::throwIAE(detail::str("VertexBuffer::getPositions: scaleBias has length ", scaleBias.size(),
                                         ", needs at least 4"));
        scaleBias[0] = positionScale_;
        for (int i = 0; i < 3; ++i) scaleBias[1 + i] = positionBias_[i];
    }
    return positions_;
}

Ref<VertexArray> VertexBuffer::getTexCoords(int index, std::span<float> scaleBias) const {
    detail::requireIndex(index, getLimits().numTextureUnits, "VertexBuffer::getTexCoords", "index");
    const VertexArray* a = texCoords_[index].get();
    if (a && scaleBias.data()) {
        const std::size_t needed = static_cast<std::size_t>(a->getComponentCount()) + 1;
        if (scaleBias.size() < needed)
            detail::throwIAE(detail::str("VertexBuffer::getTexCoords: scaleBias has length ", scaleBias.size(),
                                         ", needs at least ", needed));
        scaleBias[0] = texCoordScale_[index];
        for (int i = 0; i < a->getComponentCount(); ++i) scaleBias[1 + i] = texCoordBias_[index][i];
    }
    return texCoords_[index];
}

void VertexBuffer::setDefaultColor(int ARGB) noexcept {
    defaultColor_ = static_cast<std::uint32_t>(ARGB);
    touch();
}

bool VertexBuffer::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::COLOR || property == AnimationTrack::ALPHA || Object3D::isAnimatable(property);
}


void VertexBuffer::updateProperty(int property, std::span<const float> value) {
    switch (property) {
    case AnimationTrack::ALPHA:
        defaultColor_ = (defaultColor_ & 0x00FFFFFFu) | static_cast<std::uint32_t>(detail::packAlpha(value[0]));
        touch();
        return;
    case AnimationTrack::COLOR:
        defaultColor_ = (defaultColor_ & 0xFF000000u) |
                        static_cast<std::uint32_t>(detail::packRGB(value[0], value[1], value[2]));
        touch();
        return;
    default:
        Object3D::updateProperty(property, value);
    }
}

}  // namespace m3g
