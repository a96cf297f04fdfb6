// LLVMFuzzerTestOneInput for one check of FuzzChecks.h: a Failure is printed
// and aborts, which libFuzzer records as a crash and saves the input.
#pragma once

#include <cstdio>
#include <cstdlib>

#include "FuzzChecks.h"

#define M3G_FUZZ_TARGET(check)                                                             \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {   \
        try {                                                                              \
            check(std::span<const std::uint8_t>(data, size));                              \
        } catch (const ::m3gfuzz::Failure& f) {                                            \
            std::fprintf(stderr, "m3g fuzz expectation failed: %s\n", f.what.c_str());     \
            std::abort();                                                                  \
        }                                                                                  \
        return 0;                                                                          \
    }
