// M3G Appearance -> glTF material, texture, sampler and PNG image (glTF 2.0
// §3.9 materials, §3.8 textures; KHR_materials_unlit). The mapping table and
// its approximations are in docs/export.md. Part of the `m3g export` tool.
#pragma once

#include <map>
#include <string>
#include <utility>

#include "GltfDocument.h"
#include "GltfNotes.h"

namespace m3g {
class Appearance;
class Image2D;
class Texture2D;
class VertexBuffer;
}  // namespace m3g

namespace m3gcli::gltf {

/// What a primitive needs besides its material index.
struct PrimitiveLook {
    int material = -1;
    /// Texture unit whose coordinates become TEXCOORD_0 (-1: no texture).
    int textureUnit = -1;
    /// The texture of that unit (its transform is baked into TEXCOORD_0).
    const m3g::Texture2D* texture = nullptr;
    /// COLOR_0 carries the vertex colours (lighting off, or vertex colour
    /// tracking on, with a colour array).
    bool vertexColors = false;
    /// Reverse each triangle: WINDING_CW, or CULL_FRONT (glTF only culls
    /// back faces, so front-face culling becomes back-face culling of the
    /// reversed triangles; normals are kept).
    bool flipWinding = false;
};

class MaterialWriter {
public:
    MaterialWriter(Document& doc, Notes& notes) : doc_(doc), notes_(notes) {}

    /// The material of a submesh drawn with `appearance` from `vb` by a node
    /// whose (inherited) alpha factor is `alphaFactor`. Equal materials are
    /// written once.
    PrimitiveLook look(const m3g::Appearance& appearance, const m3g::VertexBuffer& vb, float alphaFactor);

    /// The glTF image of an Image2D (PNG, every format and palettised
    /// images expanded as Image2D::getPixelsRGBA8 does), written once.
    int image(const m3g::Image2D& image);

private:
    int texture(const m3g::Texture2D& texture);

    Document& doc_;
    Notes& notes_;
    std::map<std::string, int> materials_;  // serialised material -> index
    std::map<std::string, int> samplers_;
    std::map<const m3g::Image2D*, int> images_;
    std::map<std::pair<int, int>, int> textures_;  // (image, sampler) -> texture
};

}  // namespace m3gcli::gltf
