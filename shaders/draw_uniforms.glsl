// Per-draw uniform block of the fixed-function uber shader (std140).
// Mirrored field by field by render-vk/DrawUniforms.h; keep both in step.

struct Light {
    vec4 position;    // eye space; w = 0 for directional (xyz = direction towards the light)
    vec4 color;       // rgb = intensity x colour (may be negative or > 1); a = mode (0 ambient, 1 directional, 2 omni, 3 spot)
    vec4 spot;        // xyz = spot direction (eye space, unit), w = cos(spot angle)
    vec4 attenuation; // constant, linear, quadratic, spot exponent
};

// flags bits
const int F_LIGHTING = 1;         // Appearance has a Material
const int F_COLOR_TRACKING = 2;   // ambient and diffuse follow the vertex colour
const int F_TWO_SIDED = 4;        // back faces lit with negated normals
const int F_FLAT = 8;             // SHADE_FLAT: provoking vertex colour
const int F_HAS_NORMALS = 16;
const int F_HAS_COLORS = 32;      // else defaultColor
const int F_LOCAL_CAMERA = 64;    // specular with the real eye vector
const int F_CLIP_SPACE = 128;     // positions are NDC already (sprites, background)
const int F_CLAMP_LIT = 256;      // clamp lit colours to [0, 1] per vertex (GL ES 1.1 spec); else as Mesa's GL ES 1.1

// texEnv.x function: 0 = unit off, 1 REPLACE, 2 MODULATE, 3 DECAL, 4 BLEND, 5 ADD
// texEnv.y: texture has colour channels; texEnv.z: texture has alpha;
// texEnv.w: bit 0 / bit 1 = discard fragments with s / t outside [0, 1] (Background BORDER)

struct DrawData {
    mat4 modelView;
    mat4 projection;        // M3G projection with the Vulkan clip-space fix-up folded in
    mat4 normalMatrix;      // inverse transpose of modelView's 3x3 (in a mat4 for layout)
    mat4 texMatrix[2];      // Texture2D composite transforms
    vec4 positionScaleBias; // xyz bias, w scale
    vec4 texScaleBias[2];   // xyz bias, w scale
    vec4 matAmbient;
    vec4 matDiffuse;
    vec4 matEmissive;
    vec4 matSpecular;       // w = shininess
    vec4 defaultColor;
    vec4 fogColor;
    vec4 fogParams;         // x mode (0 off, 1 linear, 2 exponential), y near, z far, w density
    vec4 texBlendColor[2];
    ivec4 texEnv[2];
    ivec4 flags;            // x flag bits, y light count
    vec4 misc;              // x alpha factor, y alpha threshold, z fixed fog depth (>= 0: use it), w unused
    Light lights[8];
};

// Every field is read through draws[index.x] (index.x is always 0), so no
// load has a constant offset. Mesa 22.3's lavapipe "inlines" UBO values
// read at constant offsets that decide a branch or a loop count (the light
// loop, the flag tests) and then compiles a new shader variant at every
// descriptor bind, that is at every draw, with no cache: ~5 ms and ~300 KB
// that is never returned per draw. A dynamic index makes those values
// ordinary data; the index itself decides no branch.
layout(std140, set = 0, binding = 0) uniform DrawUniforms {
    ivec4 index;
    DrawData draws[1];
} drawBlock;
#define u drawBlock.draws[drawBlock.index.x]
