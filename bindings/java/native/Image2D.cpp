// javax.microedition.m3g.Image2D's native methods (JSR-184 1.1, Image2D).
// Image2D(int format, Object image) takes a java.awt.image.BufferedImage on
// desktop Java (where JSR-184 has an lcdui Image): the Java side reads its
// pixels as ARGB ints and this file converts them to the format asked for.
#include <cstdint>
#include <vector>

#include <m3g/Image2D.h>

#include "Arrays.h"
#include "Jni.h"

using namespace m3gjni;
using m3g::Image2D;

namespace {

// Byte count of a width x height image of `format` (the copy limit; 0 for
// an invalid format or size, which the C++ API rejects before reading).
std::size_t bytesFor(jint format, jint width, jint height) {
    return elementsFor({width, height, Image2D::bytesPerPixel(format)});
}

// The luminance of an ARGB pixel as Nokia's M3G implementation (reference)
// computes it when an Image2D is made from an lcdui Image: Rec. 601 weights
// in 16-bit fixed point (0x4CB2, 0x9691, 0x1D3E, summing to a little over
// 1.0 so that white stays 255), truncated.
std::uint8_t luminance(std::uint32_t argb) {
    const std::uint32_t r = (argb >> 16) & 0xFFu, g = (argb >> 8) & 0xFFu, b = argb & 0xFFu;
    return static_cast<std::uint8_t>((0x4CB2u * r + 0x9691u * g + 0x1D3Eu * b) >> 16);
}

// The pixels of `format` (bytesPerPixel(format) > 0) from ARGB ints. An
// image without alpha gives ALPHA its luminance (opaque everywhere would be
// useless as an alpha map), as Nokia's M3G implementation (reference) does
// for lcdui images without alpha; its other formats take alpha 0xFF from
// getRGB.
std::vector<std::uint8_t> fromArgb(int format, std::span<const std::int32_t> argb, bool hasAlpha) {
    std::vector<std::uint8_t> out;
    out.reserve(argb.size() * static_cast<std::size_t>(Image2D::bytesPerPixel(format)));
    for (const std::int32_t pixel : argb) {
        const auto p = static_cast<std::uint32_t>(pixel);
        const auto a = static_cast<std::uint8_t>(p >> 24);
        const auto r = static_cast<std::uint8_t>(p >> 16);
        const auto g = static_cast<std::uint8_t>(p >> 8);
        const auto b = static_cast<std::uint8_t>(p);
        switch (format) {
        case Image2D::ALPHA: out.push_back(hasAlpha ? a : luminance(p)); break;
        case Image2D::LUMINANCE: out.push_back(luminance(p)); break;
        case Image2D::LUMINANCE_ALPHA: out.insert(out.end(), {luminance(p), a}); break;
        case Image2D::RGB: out.insert(out.end(), {r, g, b}); break;
        case Image2D::RGBA: out.insert(out.end(), {r, g, b, a}); break;
        default: break;
        }
    }
    return out;
}

}  // namespace

M3G_JNI(jlong, Image2D, createMutable)(JNIEnv* env, jclass, jint format, jint width, jint height) {
    return guard(env, [&] { return handleOf(m3g::make<Image2D>(format, width, height)); });
}

M3G_JNI(jlong, Image2D, createPixels)(JNIEnv* env, jclass, jint format, jint width, jint height, jbyteArray image) {
    return guard(env, [&] {
        SpanIn<jbyteArray> pixels(env, image, bytesFor(format, width, height));
        return handleOf(m3g::make<Image2D>(format, width, height, pixels.as<std::uint8_t>()));
    });
}

M3G_JNI(jlong, Image2D, createPalettized)(JNIEnv* env, jclass, jint format, jint width, jint height,
                                          jbyteArray image, jbyteArray palette) {
    return guard(env, [&] {
        // At most 256 palette entries are used, one index byte per pixel.
        SpanIn<jbyteArray> indices(env, image, elementsFor({width, height}));
        SpanIn<jbyteArray> entries(env, palette, elementsFor({256, Image2D::bytesPerPixel(format)}));
        return handleOf(
            m3g::make<Image2D>(format, width, height, indices.as<std::uint8_t>(), entries.as<std::uint8_t>()));
    });
}

// From the ARGB pixels of a BufferedImage (width * height ints, rows top to
// bottom, never null: the Java side read them), immutable.
M3G_JNI(jlong, Image2D, createArgb)(JNIEnv* env, jclass, jint format, jint width, jint height, jintArray argb,
                                    jboolean hasAlpha) {
    return guard(env, [&] {
        if (Image2D::bytesPerPixel(format) == 0)  // the C++ API's IllegalArgumentException for the format
            return handleOf(m3g::make<Image2D>(format, width, height));
        SpanIn<jintArray> in(env, argb, elementsFor({width, height}));
        const std::vector<std::uint8_t> pixels = fromArgb(format, in.span(), hasAlpha == JNI_TRUE);
        return handleOf(m3g::make<Image2D>(format, width, height, std::span<const std::uint8_t>(pixels)));
    });
}

M3G_JNI(void, Image2D, set)(JNIEnv* env, jobject thiz, jint x, jint y, jint width, jint height, jbyteArray image) {
    guard(env, [&] {
        Image2D* img = self<Image2D>(env, thiz);
        SpanIn<jbyteArray> pixels(env, image, elementsFor({width, height, img->bytesPerPixel()}));
        img->set(x, y, width, height, pixels.as<std::uint8_t>());
    });
}

M3G_JNI(jboolean, Image2D, isMutable)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return static_cast<jboolean>(self<Image2D>(env, thiz)->isMutable()); });
}
M3G_JNI(jint, Image2D, getFormat)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Image2D>(env, thiz)->getFormat(); });
}
M3G_JNI(jint, Image2D, getWidth)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Image2D>(env, thiz)->getWidth(); });
}
M3G_JNI(jint, Image2D, getHeight)(JNIEnv* env, jobject thiz) {
    return guard(env, [&] { return self<Image2D>(env, thiz)->getHeight(); });
}

M3G_JNI(jbyteArray, Image2D, nativePixels)(JNIEnv* env, jobject thiz) {
    return guard(env, [&]() -> jbyteArray {
        const std::span<const std::uint8_t> pixels = self<Image2D>(env, thiz)->pixels();
        jbyteArray out = env->NewByteArray(static_cast<jsize>(pixels.size()));
        if (out && !pixels.empty())
            env->SetByteArrayRegion(out, 0, static_cast<jsize>(pixels.size()),
                                    reinterpret_cast<const jbyte*>(pixels.data()));
        return out;
    });
}
