#include <m3g/Limits.h>

#include "Check.h"

namespace m3g {

namespace {
Limits g_limits;
}

const Limits& getLimits() noexcept { return g_limits; }

void setLimits(const Limits& l) {
    auto atLeast = [](int v, int min, const char* name) {
        if (v < min)
            throw IllegalArgumentException(detail::str("m3g::setLimits: ", name, " ", v, " is below the spec minimum ", min));
    };
    atLeast(l.maxLights, 8, "maxLights");
    atLeast(l.maxViewportWidth, 256, "maxViewportWidth");
    atLeast(l.maxViewportHeight, 256, "maxViewportHeight");
    atLeast(l.maxViewportDimension, 256, "maxViewportDimension");
    atLeast(l.maxTextureDimension, 256, "maxTextureDimension");
    atLeast(l.maxSpriteCropDimension, 256, "maxSpriteCropDimension");
    atLeast(l.maxTransformsPerVertex, 2, "maxTransformsPerVertex");
    detail::requireRange(l.numTextureUnits, 1, kMaxTextureUnits, "m3g::setLimits", "numTextureUnits");
    g_limits = l;
}

}  // namespace m3g
