// M3G_API marks what the shared libraries export (docs/library.md): a
// -DBUILD_SHARED_LIBS=ON build compiles everything with hidden visibility,
// so libm3g.so and libm3g_scene.so export the public classes and functions
// of these headers and nothing of their insides. Harmless in a static build.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define M3G_API __attribute__((visibility("default")))
#else
#define M3G_API
#endif
