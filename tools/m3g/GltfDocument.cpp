#include "GltfDocument.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <m3g/Version.h>

namespace m3gcli::gltf {

namespace {

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

template <class T>
std::span<const std::uint8_t> asBytes(std::span<const T> values) {
    return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

}  // namespace

int componentCount(const char* type) {
    const std::string t = type;
    if (t == "SCALAR") return 1;
    if (t == "VEC2") return 2;
    if (t == "VEC3") return 3;
    if (t == "VEC4") return 4;
    if (t == "MAT4") return 16;
    throw std::invalid_argument("glTF: unknown accessor type " + t);
}

Document::Document() {
    json_["asset"] = {{"version", "2.0"}, {"generator", std::string("m3g-vk ") + m3g::kVersionString + " m3g export"}};
}

int Document::add(const char* key, Json value) {
    Json& array = json_[key];
    if (!array.is_array()) array = Json::array();
    array.push_back(std::move(value));
    return static_cast<int>(array.size()) - 1;
}

void Document::useExtension(const std::string& name) {
    Json& used = json_["extensionsUsed"];
    if (!used.is_array()) used = Json::array();
    if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
}

int Document::addView(std::span<const std::uint8_t> bytes, ViewTarget target) {
    while (bin_.size() % 4) bin_.push_back(0);
    Json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}};
    if (target != ViewTarget::None) view["target"] = static_cast<int>(target);
    bin_.insert(bin_.end(), bytes.begin(), bytes.end());
    return add("bufferViews", std::move(view));
}

int Document::addFloatAccessor(std::span<const float> values, const char* type, ViewTarget target, bool bounds) {
    const int comps = componentCount(type);
    const std::size_t count = values.size() / static_cast<std::size_t>(comps);
    const int view = addView(asBytes(values), target);
    Json acc = {{"bufferView", view},
                {"componentType", static_cast<int>(ComponentType::Float)},
                {"count", count},
                {"type", type}};
    if (bounds && count > 0) {
        // The validator compares these with the stored float32 values, so
        // they are written as the exact doubles of those floats.
        std::vector<double> lo(static_cast<std::size_t>(comps), std::numeric_limits<double>::infinity());
        std::vector<double> hi(static_cast<std::size_t>(comps), -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < values.size(); ++i) {
            const std::size_t c = i % static_cast<std::size_t>(comps);
            lo[c] = std::min(lo[c], static_cast<double>(values[i]));
            hi[c] = std::max(hi[c], static_cast<double>(values[i]));
        }
        acc["min"] = lo;
        acc["max"] = hi;
    }
    return add("accessors", std::move(acc));
}

int Document::addIndexAccessor(std::span<const std::uint32_t> indices) {
    const std::uint32_t maxIndex = indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end());
    int view;
    ComponentType ct;
    if (maxIndex < 65535) {
        std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
        view = addView(asBytes(std::span<const std::uint16_t>(shorts)), ViewTarget::ElementArrayBuffer);
        ct = ComponentType::UnsignedShort;
    } else {
        view = addView(asBytes(indices), ViewTarget::ElementArrayBuffer);
        ct = ComponentType::UnsignedInt;
    }
    return add("accessors", {{"bufferView", view},
                             {"componentType", static_cast<int>(ct)},
                             {"count", indices.size()},
                             {"type", "SCALAR"}});
}

int Document::addByteAccessor(std::span<const std::uint8_t> values, const char* type, bool normalized) {
    const std::size_t count = values.size() / static_cast<std::size_t>(componentCount(type));
    const int view = addView(values, ViewTarget::ArrayBuffer);
    Json acc = {{"bufferView", view},
                {"componentType", static_cast<int>(ComponentType::UnsignedByte)},
                {"count", count},
                {"type", type}};
    if (normalized) acc["normalized"] = true;
    return add("accessors", std::move(acc));
}

int Document::addShortAccessor(std::span<const std::uint16_t> values, const char* type, bool normalized) {
    const std::size_t count = values.size() / static_cast<std::size_t>(componentCount(type));
    const int view = addView(asBytes(values), ViewTarget::ArrayBuffer);
    Json acc = {{"bufferView", view},
                {"componentType", static_cast<int>(ComponentType::UnsignedShort)},
                {"count", count},
                {"type", type}};
    if (normalized) acc["normalized"] = true;
    return add("accessors", std::move(acc));
}

int Document::addPngImage(std::span<const std::uint8_t> png, const std::string& name) {
    const int view = addView(png, ViewTarget::None);
    Json image = {{"bufferView", view}, {"mimeType", "image/png"}};
    if (!name.empty()) image["name"] = name;
    return add("images", std::move(image));
}

Json Document::finalJson(const std::string& uri) const {
    Json out = json_;
    if (!bin_.empty()) {
        Json buffer = {{"byteLength", bin_.size()}};
        if (!uri.empty()) buffer["uri"] = uri;
        out["buffers"] = Json::array({std::move(buffer)});
    }
    return out;
}

std::vector<std::uint8_t> Document::toGlb() const {
    std::string text = finalJson("").dump(-1, ' ', false, Json::error_handler_t::replace);
    while (text.size() % 4) text.push_back(' ');
    std::vector<std::uint8_t> bin = bin_;
    while (bin.size() % 4) bin.push_back(0);
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    if (total > std::numeric_limits<std::uint32_t>::max())
        throw std::runtime_error("glTF: the scene is larger than the 4 GiB a GLB file can hold");
    std::vector<std::uint8_t> out;
    out.reserve(total);
    appendU32(out, 0x46546C67u);  // "glTF"
    appendU32(out, 2);
    appendU32(out, static_cast<std::uint32_t>(total));
    appendU32(out, static_cast<std::uint32_t>(text.size()));
    appendU32(out, 0x4E4F534Au);  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    if (!bin.empty()) {
        appendU32(out, static_cast<std::uint32_t>(bin.size()));
        appendU32(out, 0x004E4942u);  // "BIN\0"
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

std::string Document::toGltf(const std::string& binUri) const {
    const std::string uri = binUri.empty() && !bin_.empty()
                                ? "data:application/octet-stream;base64," + base64(bin_)
                                : binUri;
    return finalJson(uri).dump(1, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string base64(std::span<const std::uint8_t> bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (int s = 18; s >= 0; s -= 6) out.push_back(kAlphabet[(v >> s) & 63]);
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const std::uint32_t v = (bytes[i] << 16) | (two ? bytes[i + 1] << 8 : 0);
        out.push_back(kAlphabet[(v >> 18) & 63]);
        out.push_back(kAlphabet[(v >> 12) & 63]);
        out.push_back(two ? kAlphabet[(v >> 6) & 63] : '=');
        out.push_back('=');
    }
    return out;
}

}  // namespace m3gcli::gltf
