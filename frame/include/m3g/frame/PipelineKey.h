// The identity of a draw's pipeline: the fixed-function state that a back end
// compiles into a pipeline (blending, write mask, the fragment and vertex
// shader features a draw uses). Everything else is uniform data
// (DrawUniforms) or dynamic state (RasterState). Scene derives the key from
// the M3G state (StateTranslation); the back end adds the sample count.
#pragma once

#include <cstdint>

namespace m3g::frame {

/// Colour write mask bits (the values of VkColorComponentFlagBits).
enum WriteMask : std::uint8_t { WRITE_R = 1, WRITE_G = 2, WRITE_B = 4, WRITE_A = 8, WRITE_RGBA = 15 };

struct PipelineKey {
    std::uint8_t blend = 0;        ///< 0 REPLACE, 1 ALPHA, 2 ALPHA_ADD, 3 MODULATE, 4 MODULATE_X2
    std::uint8_t writeMask = WRITE_RGBA;
    std::uint8_t samples = 1;      ///< set by the back end (multisampling)
    std::uint8_t wireframe = 0;    ///< 1: polygon mode LINE (a viewer's debug view)
    // Fragment-shader features, m3g.frag's specialization constants. A
    // feature a draw does not use is compiled out rather than skipped by a
    // uniform branch: llvmpipe runs both sides of a branch under a lane mask,
    // so a disabled texture unit or fog still cost their full work
    // (docs/rendering.md, "Shader variants").
    /// 1: the discards stay (alpha threshold, Background BORDER). Without them
    /// a rasteriser can also test depth before shading (llvmpipe does).
    std::uint8_t discard = 0;
    /// Per texture unit: its function (DrawUniforms.h TexFunc, 0 = off) and
    /// its image's channels (bit 0 colour, bit 1 alpha).
    std::uint8_t texFunc[2] = {0, 0};
    std::uint8_t texFormat[2] = {0, 0};
    /// Per texture unit, 1: the texture matrix is projective (bottom row not
    /// 0, 0, 0, 1), so the fragment shader divides s and t by q.
    std::uint8_t texProjective[2] = {0, 0};
    std::uint8_t fog = 0;   ///< 1: fog applied
    std::uint8_t flat = 0;  ///< 1: SHADE_FLAT
    /// Bit 0 lighting, bit 1 two-sided lighting (m3g.vert, and m3g.frag's
    /// choice of back-face colours).
    std::uint8_t lighting = 0;
    /// With lighting, m3g.vert's lights: how many (0..8), each one's mode
    /// (light i in bits 2i..2i+1: 0 ambient, 1 directional, 2 omni, 3 spot)
    /// and whether the material's specular colour is not black. A light's
    /// mode is compiled in instead of branched on (llvmpipe ran every mode's
    /// code for every light).
    std::uint8_t lightCount = 0;
    std::uint16_t lightModes = 0;
    std::uint8_t specular = 0;

    /// Every field in one word: the pipeline cache's key.
    std::uint64_t packed() const noexcept {
        auto at = [](std::uint64_t v, int bit) { return v << bit; };
        return at(blend, 0) | at(writeMask, 4) | at(samples, 8) | at(wireframe, 16) | at(discard, 17) |
               at(texFunc[0], 18) | at(texFunc[1], 21) | at(texFormat[0], 24) | at(texFormat[1], 26) | at(fog, 28) |
               at(flat, 29) | at(lighting, 30) | at(lightCount, 32) | at(lightModes, 36) | at(specular, 52) |
               at(texProjective[0], 53) | at(texProjective[1], 54);
    }
};

}  // namespace m3g::frame
