// A glTF 2.0 document being built: the JSON tree (nlohmann::ordered_json)
// and one binary buffer, with helpers that append typed accessors, and the
// two container formats (.glb with a BIN chunk, .gltf with a data: URI or a
// side .bin file). Part of the `m3g export` tool (tools/m3g/), not of the
// library. glTF 2.0 specification §3.6 (buffers, views, accessors), §4.4 (GLB).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace m3gcli::gltf {

using Json = nlohmann::ordered_json;

/// glTF componentType values (§3.6.2.2).
enum class ComponentType : int {
    UnsignedByte = 5121,
    UnsignedShort = 5123,
    UnsignedInt = 5125,
    Float = 5126,
};

/// bufferView.target values; None leaves the property out (animation,
/// inverse bind matrices, images).
enum class ViewTarget : int { None = 0, ArrayBuffer = 34962, ElementArrayBuffer = 34963 };

class Document {
public:
    Document();

    Json& json() noexcept { return json_; }
    const Json& json() const noexcept { return json_; }
    const std::vector<std::uint8_t>& binary() const noexcept { return bin_; }

    /// Appends `value` to the top-level array `key` (created when missing)
    /// and returns its index.
    int add(const char* key, Json value);
    /// Adds `name` to extensionsUsed (once).
    void useExtension(const std::string& name);

    /// Appends bytes (4-byte aligned start) as a new bufferView; returns its index.
    int addView(std::span<const std::uint8_t> bytes, ViewTarget target);

    /// Float accessor of `count` elements of `type` ("SCALAR", "VEC2", "VEC3",
    /// "VEC4", "MAT4"); `values` holds count * components floats. With
    /// `bounds`, min and max are computed from the values (required for
    /// POSITION and animation inputs, §3.6.2.4).
    int addFloatAccessor(std::span<const float> values, const char* type, ViewTarget target, bool bounds);
    /// Index accessor (SCALAR): UNSIGNED_SHORT when every index fits below
    /// 65535 (the restart value is avoided), else UNSIGNED_INT.
    int addIndexAccessor(std::span<const std::uint32_t> indices);
    /// Unsigned byte or short accessor (normalised for colours).
    int addByteAccessor(std::span<const std::uint8_t> values, const char* type, bool normalized);
    int addShortAccessor(std::span<const std::uint16_t> values, const char* type, bool normalized);

    /// Embeds a PNG (bufferView + image with mimeType); returns the image index.
    int addPngImage(std::span<const std::uint8_t> png, const std::string& name);

    /// The .glb container: 12-byte header, JSON chunk (space padded), BIN
    /// chunk (zero padded) when the buffer is not empty.
    std::vector<std::uint8_t> toGlb() const;
    /// The .gltf JSON. With an empty `binUri` the buffer is embedded as a
    /// base64 data: URI; otherwise its uri is `binUri` (write binary() there).
    std::string toGltf(const std::string& binUri) const;

private:
    /// Finishes buffers[0] for a given uri (empty: GLB-internal).
    Json finalJson(const std::string& uri) const;

    Json json_;
    std::vector<std::uint8_t> bin_;
};

/// Number of components of an accessor type ("VEC3" -> 3, "MAT4" -> 16).
int componentCount(const char* type);

/// RFC 4648 base64 of `bytes` (for data: URIs).
std::string base64(std::span<const std::uint8_t> bytes);

}  // namespace m3gcli::gltf
