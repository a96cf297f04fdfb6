// Instruction-set selection for the skin/ kernels. Every kernel has a plain
// C++ path; on x86 there are SSE2 (the x86-64 baseline), AVX2+FMA and
// AVX-512 paths, the latter two compiled with function target attributes and
// chosen at run time from the CPU's feature bits, so one binary runs on
// every x86-64 CPU.
#pragma once

namespace m3g::skin {

enum class Isa {
    Auto,    ///< the best path this CPU supports (resolveIsa)
    Scalar,  ///< plain C++ loops (whatever the compiler makes of them)
    Sse2,    ///< 128-bit SSE2 intrinsics (x86 only)
    Avx2,    ///< 256-bit AVX2 + FMA intrinsics (x86 CPUs that report both)
    /// AVX-512F and VL for the skinning run and bone-run kernels (sixteen
    /// vertices a step, a run's last eight or fewer in 256-bit registers),
    /// the AVX2 paths for everything else (x86 CPUs that report AVX-512F,
    /// AVX-512VL, AVX2 and FMA)
    Avx512,
};

/// True if `isa` can run here (Auto and Scalar always can).
bool isaSupported(Isa isa) noexcept;
/// Auto -> the best supported path, no better than the environment variable
/// M3G_SKIN_ISA allows (`scalar`, `sse2`, `avx2`; read once per process);
/// any other value is returned unchanged.
Isa resolveIsa(Isa isa) noexcept;
/// "auto", "scalar", "sse2", "avx2", "avx512".
const char* isaName(Isa isa) noexcept;

}  // namespace m3g::skin
