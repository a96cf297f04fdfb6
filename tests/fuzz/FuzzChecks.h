// The checks of the three libFuzzer targets, shared with the regression
// replay of the unit tests (tests/unit/test_FuzzRegressions.cpp) so that a
// committed reproducer is judged by the same rules under the normal build and
// the ASan + UBSan build. A broken rule throws m3gfuzz::Failure (not a
// std::exception, so that no catch of the code under test swallows it);
// crashes, leaks and undefined behaviour are the sanitizers' to report.
// Test-only, header-only.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>
#include <m3g/Loader.h>
#include <m3g/Saver.h>

#include "FuzzInput.h"

namespace m3gfuzz {

struct Failure {
    std::string what;
};

inline void expect(bool ok, const std::string& what) {
    if (!ok) throw Failure{what};
}

/// Only IOException is an acceptable failure of a load (Loader contract);
/// anything else escaping is a Failure naming the stage.
#define M3G_FUZZ_OTHER_EXCEPTIONS_FAIL(stage)                                                   \
    catch (const ::m3gfuzz::Failure&) {                                                        \
        throw;                                                                                 \
    }                                                                                          \
    catch (const std::exception& e) {                                                          \
        throw ::m3gfuzz::Failure{std::string(stage) + ": unexpected exception: " + e.what()}; \
    }                                                                                          \
    catch (...) {                                                                              \
        throw ::m3gfuzz::Failure{std::string(stage) + ": unexpected non-std exception"};      \
    }

/// Loader target, one form of the input: strict and lenient loads. A file
/// the strict loader accepts has no fault for the lenient one to tolerate, so
/// the lenient load must give the same objects and no warning.
inline void checkLoaderOnce(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) return;  // IndexOutOfBoundsException by contract (offset >= size)
    bool strictLoaded = false;
    std::size_t strictObjects = 0, strictRoots = 0;
    try {
        const m3g::LoadResult r = m3g::Loader::loadDetailed(bytes, 0);
        strictLoaded = true;
        strictObjects = r.objects.size();
        strictRoots = r.roots.size();
        expect(r.warnings.empty(), "strict load reported warnings");
    } catch (const m3g::IOException&) {
    }
    M3G_FUZZ_OTHER_EXCEPTIONS_FAIL("strict load")

    m3g::LoaderOptions lenient;
    lenient.lenient = true;
    try {
        const m3g::LoadResult r = m3g::Loader::loadDetailed(bytes, 0, lenient);
        if (strictLoaded) {
            expect(r.objects.size() == strictObjects && r.roots.size() == strictRoots,
                   "lenient load of a strictly valid file gave other objects");
            expect(r.warnings.empty(),
                   "lenient load of a strictly valid file warned: " + (r.warnings.empty() ? "" : r.warnings[0]));
        }
    } catch (const m3g::IOException& e) {
        if (strictLoaded) throw Failure{std::string("lenient load failed where strict loaded: ") + e.what()};
    }
    M3G_FUZZ_OTHER_EXCEPTIONS_FAIL("lenient load")
}

/// An image file's rules (the png and jpeg targets): a load through the
/// Loader gives an IOException or one immutable Image2D within the decoders'
/// limits (1..16384 a side), of a format `allowed` accepts, whose pixel store
/// matches its size and format (JSR-184 1.1, Loader). `kind` names the file
/// kind in the messages.
template <class Allowed>
void checkImageLoad(std::span<const std::uint8_t> bytes, const std::string& kind, Allowed allowed) {
    if (bytes.empty()) return;
    try {
        const m3g::LoadResult r = m3g::Loader::loadDetailed(bytes, 0);
        if (r.versionMajor != 0) return;  // bytes that sniff as .m3g: the loader target's business
        expect(r.objects.size() == 1 && r.roots.size() == 1, "a " + kind + " must give exactly one object");
        const auto* image = dynamic_cast<const m3g::Image2D*>(r.objects[0].get());
        expect(image != nullptr, "a " + kind + " must give an Image2D");
        expect(!image->isMutable(), "a " + kind + " Image2D must be immutable");
        expect(allowed(image->getFormat()), kind + " Image2D format out of range");
        const int w = image->getWidth(), h = image->getHeight();
        expect(w >= 1 && h >= 1 && w <= 16384 && h <= 16384, kind + " Image2D size out of range");
        const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        expect(image->pixels().size() == pixels * static_cast<std::size_t>(image->bytesPerPixel()),
               kind + " Image2D pixel store does not match width * height * bpp");
        std::vector<std::uint8_t> rgba;
        image->getPixelsRGBA8(rgba);
        expect(rgba.size() == pixels * 4, "getPixelsRGBA8 size");
    } catch (const m3g::IOException&) {
    }
    M3G_FUZZ_OTHER_EXCEPTIONS_FAIL(kind + " load")
}

/// PNG target, one form of the input: any of the four formats a PNG decodes to.
inline void checkPngOnce(std::span<const std::uint8_t> bytes) {
    checkImageLoad(bytes, "PNG", [](int f) {
        return f == m3g::Image2D::LUMINANCE || f == m3g::Image2D::LUMINANCE_ALPHA || f == m3g::Image2D::RGB ||
               f == m3g::Image2D::RGBA;
    });
}

/// JPEG target: greyscale (LUMINANCE) or colour (RGB). JPEG has no
/// checksums to repair: the input is checked as given.
inline void checkJpeg(std::span<const std::uint8_t> bytes) {
    checkImageLoad(bytes, "JPEG", [](int f) { return f == m3g::Image2D::LUMINANCE || f == m3g::Image2D::RGB; });
}

/// Round-trip target, one form of the input: whatever loads (leniently, the
/// most permissive load) must save, plain and zlib-compressed, and the saved
/// bytes must load again strictly with the same numbers of roots and objects:
/// the Saver writes only what the strict Loader accepts and drops nothing.
inline void checkRoundTripOnce(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) return;
    m3g::LoaderOptions lenient;
    lenient.lenient = true;
    m3g::LoadResult first;
    try {
        first = m3g::Loader::loadDetailed(bytes, 0, lenient);
    } catch (const m3g::IOException&) {
        return;  // not loadable: nothing to round-trip
    }
    M3G_FUZZ_OTHER_EXCEPTIONS_FAIL("first load")

    std::vector<m3g::Object3D*> roots;
    for (const auto& r : first.roots) roots.push_back(r.get());
    // A file with no objects loads as an empty list, which must save as an
    // empty file. An empty vector's data() may be null, which the C++ API reads
    // as Java null (docs/conventions.md): give the span a non-null pointer.
    // (The fuzzer's first round-trip finding was this harness mistake.)
    m3g::Object3D* const none = nullptr;
    const std::span<m3g::Object3D* const> rootSpan =
        roots.empty() ? std::span<m3g::Object3D* const>(&none, 0) : std::span<m3g::Object3D* const>(roots);
    for (bool compress : {false, true}) {
        const std::string mode = compress ? "zlib" : "plain";
        m3g::SaverOptions so;
        so.compress = compress;
        std::vector<std::uint8_t> saved;
        try {
            saved = m3g::Saver::save(rootSpan, so);
        } catch (const std::exception& e) {
            throw Failure{"save (" + mode + ") of a loaded graph failed: " + e.what()};
        }
        try {
            const m3g::LoadResult again = m3g::Loader::loadDetailed(std::span<const std::uint8_t>(saved), 0);
            expect(again.roots.size() == first.roots.size(),
                   "reload (" + mode + "): " + std::to_string(again.roots.size()) + " roots, loaded " +
                       std::to_string(first.roots.size()));
            expect(again.objects.size() == first.objects.size(),
                   "reload (" + mode + "): " + std::to_string(again.objects.size()) + " objects, loaded " +
                       std::to_string(first.objects.size()));
        } catch (const Failure&) {
            throw;
        } catch (const std::exception& e) {
            throw Failure{"strict reload (" + mode + ") of saved bytes failed: " + e.what()};
        }
    }
}

/// A check on the input as given and, if different, on its checksum-repaired
/// form (FuzzInput.h). The as-given form runs only the first check when the
/// two differ: its checksums are wrong, so it cannot get past the sections.
template <class Check>
void checkBothForms(std::span<const std::uint8_t> data, Check check) {
    const Bytes repaired = repairChecksums(data);
    check(std::span<const std::uint8_t>(repaired));
    if (!std::equal(repaired.begin(), repaired.end(), data.begin(), data.end())) check(data);
}

inline void checkLoader(std::span<const std::uint8_t> data) { checkBothForms(data, checkLoaderOnce); }
inline void checkPng(std::span<const std::uint8_t> data) { checkBothForms(data, checkPngOnce); }
inline void checkRoundTrip(std::span<const std::uint8_t> data) { checkBothForms(data, checkRoundTripOnce); }

}  // namespace m3gfuzz
