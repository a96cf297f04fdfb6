// Hand-made object records for the Loader tests (JSR-184 1.1
// file format, section "Per-Class Data"):
// inherited blocks and per-class data written field by field. Test-only.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <m3g/Loader.h>

#include "M3GTestBytes.h"

namespace m3gtest {

/// A Writer with the .m3g composite types.
struct O {
    Writer w;
    O& u8(std::uint8_t v) { w.u8(v); return *this; }
    O& u16(std::uint16_t v) { w.u16(v); return *this; }
    O& u32(std::uint32_t v) { w.u32(v); return *this; }
    O& i32(std::int32_t v) { w.i32(v); return *this; }
    O& f32(float v) { w.f32(v); return *this; }
    O& str(const std::string& s) { w.str(s); return *this; }
    O& bytes(const Bytes& x) { w.bytes(x); return *this; }
    O& boolean(bool v) { u8(v ? 1 : 0); return *this; }
    O& vec3(float x, float y, float z) { f32(x).f32(y).f32(z); return *this; }
    O& rgb(std::uint8_t r, std::uint8_t g, std::uint8_t bl) { u8(r).u8(g).u8(bl); return *this; }
    O& rgba(std::uint8_t r, std::uint8_t g, std::uint8_t bl, std::uint8_t a) { u8(r).u8(g).u8(bl).u8(a); return *this; }
    O& ref(std::uint32_t index) { u32(index); return *this; }
    O& refs(const std::vector<std::uint32_t>& v) {
        u32(static_cast<std::uint32_t>(v.size()));
        for (auto x : v) u32(x);
        return *this;
    }
    /// Object3D block.
    O& obj3d(std::uint32_t userID = 0, const std::vector<std::uint32_t>& tracks = {},
             const std::vector<std::pair<std::uint32_t, Bytes>>& params = {}) {
        u32(userID);
        refs(tracks);
        u32(static_cast<std::uint32_t>(params.size()));
        for (const auto& [id, value] : params) {
            u32(id).u32(static_cast<std::uint32_t>(value.size()));
            bytes(value);
        }
        return *this;
    }
    /// Transformable block without transforms.
    O& noTransform() { boolean(false).boolean(false); return *this; }
    /// Node block with default values (rendering and picking on, alpha 1, scope -1, no alignment).
    O& nodeDefaults() { boolean(true).boolean(true).u8(255).u32(0xFFFFFFFFu).boolean(false); return *this; }
    /// Object3D + Transformable + Node blocks, all default.
    O& plainNode(std::uint32_t userID = 0) { obj3d(userID).noTransform().nodeDefaults(); return *this; }
    Bytes as(std::uint8_t type) const { return object(type, w.b); }
};

/// A file with one uncompressed scene section holding `objects` (ObjectIndex
/// of objects[i] is i + 2).
inline Bytes sceneFile(const std::vector<Bytes>& objects, int scheme = 0) {
    FileSpec f;
    f.sections.push_back({scheme, objects});
    return f.build();
}

inline m3g::LoadResult loadObjects(const std::vector<Bytes>& objects, bool lenient = false, int scheme = 0) {
    const Bytes file = sceneFile(objects, scheme);
    m3g::LoaderOptions o;
    o.lenient = lenient;
    return m3g::Loader::loadDetailed(std::span<const std::uint8_t>(file), 0, o);
}

// ---- common objects ----

/// VertexArray (type 20), encoding 0.
inline Bytes vertexArray8(int components, const std::vector<std::int8_t>& values, std::uint32_t userID = 0) {
    O o;
    o.obj3d(userID).u8(1).u8(std::uint8_t(components)).u8(0).u16(std::uint16_t(values.size() / components));
    for (auto v : values) o.u8(std::uint8_t(v));
    return o.as(20);
}
inline Bytes vertexArray16(int components, const std::vector<std::int16_t>& values, std::uint32_t userID = 0) {
    O o;
    o.obj3d(userID).u8(2).u8(std::uint8_t(components)).u8(0).u16(std::uint16_t(values.size() / components));
    for (auto v : values) o.u16(std::uint16_t(v));
    return o.as(20);
}
/// VertexBuffer (type 21) with positions only.
inline Bytes vertexBufferWithPositions(std::uint32_t positions) {
    O o;
    o.obj3d().rgba(255, 255, 255, 255).ref(positions).vec3(0, 0, 0).f32(1).ref(0).ref(0).u32(0);
    return o.as(21);
}
/// Implicit TriangleStripArray (type 11), 32-bit start.
inline Bytes stripArray(std::uint32_t start, const std::vector<std::uint32_t>& lengths) {
    O o;
    o.obj3d().u8(0).u32(start);
    o.u32(static_cast<std::uint32_t>(lengths.size()));
    for (auto l : lengths) o.u32(l);
    return o.as(11);
}
/// Empty Appearance (type 3).
inline Bytes emptyAppearance() {
    O o;
    o.obj3d().u8(0).ref(0).ref(0).ref(0).ref(0).u32(0);
    return o.as(3);
}
/// Group (type 9) with children.
inline Bytes group(const std::vector<std::uint32_t>& children, std::uint32_t userID = 0) {
    O o;
    o.plainNode(userID).refs(children);
    return o.as(9);
}
/// RGB Image2D (type 10) of w x h, all pixels `value`.
inline Bytes rgbImage(std::uint32_t w, std::uint32_t h, std::uint8_t value = 0x80) {
    O o;
    o.obj3d().u8(99).boolean(false).u32(w).u32(h).u32(0).u32(w * h * 3);
    for (std::uint32_t i = 0; i < w * h * 3; ++i) o.u8(value);
    return o.as(10);
}

}  // namespace m3gtest
