#include <m3g/skin/Isa.h>

#include <cstdlib>
#include <string_view>

namespace m3g::skin {

namespace {
bool cpuHasAvx2Fma() noexcept {
#if defined(__x86_64__) || defined(__i386__)
    // __builtin_cpu_supports also checks that the OS saves the YMM state.
    static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return has;
#else
    return false;
#endif
}
bool cpuHasAvx512() noexcept {
#if defined(__x86_64__) || defined(__i386__)
    // Also checks that the OS saves the ZMM and mask state. VL: the kernels
    // take a run's last eight vertices or fewer in 256-bit registers with
    // the AVX-512 forms (every AVX-512 core since Skylake-SP has it).
    static const bool has =
        cpuHasAvx2Fma() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    return has;
#else
    return false;
#endif
}
/// The most Auto may pick: M3G_SKIN_ISA=scalar, sse2 or avx2 holds it below
/// the best path (to run a whole program, the renderer's deformation
/// included, on those kernels); unset or anything else, no limit. Read once.
Isa autoLimit() noexcept {
    static const Isa limit = [] {
        const char* value = std::getenv("M3G_SKIN_ISA");
        const std::string_view v = value ? value : "";
        if (v == "scalar") return Isa::Scalar;
        if (v == "sse2") return Isa::Sse2;
        if (v == "avx2") return Isa::Avx2;
        return Isa::Avx512;
    }();
    return limit;
}
}  // namespace

bool isaSupported(Isa isa) noexcept {
    switch (isa) {
        case Isa::Auto:
        case Isa::Scalar: return true;
#if defined(__x86_64__) || defined(__i386__)
        case Isa::Sse2: return __builtin_cpu_supports("sse2");
#else
        case Isa::Sse2: return false;
#endif
        case Isa::Avx2: return cpuHasAvx2Fma();
        case Isa::Avx512: return cpuHasAvx512();
    }
    return false;
}

Isa resolveIsa(Isa isa) noexcept {
    if (isa != Isa::Auto) return isa;
    // Resolved once: every skinning and palette job of every mesh asks.
    static const Isa resolved = [] {
        const Isa limit = autoLimit();
        if (limit == Isa::Avx512 && isaSupported(Isa::Avx512)) return Isa::Avx512;
        if ((limit == Isa::Avx2 || limit == Isa::Avx512) && isaSupported(Isa::Avx2)) return Isa::Avx2;
        if (limit != Isa::Scalar && isaSupported(Isa::Sse2)) return Isa::Sse2;
        return Isa::Scalar;
    }();
    return resolved;
}

const char* isaName(Isa isa) noexcept {
    switch (isa) {
        case Isa::Auto: return "auto";
        case Isa::Scalar: return "scalar";
        case Isa::Sse2: return "sse2";
        case Isa::Avx2: return "avx2";
        case Isa::Avx512: return "avx512";
    }
    return "?";
}

}  // namespace m3g::skin
