// M3G_FRAME_API: what libm3g_scene.so exports of the frame interface for
// libm3g.so's back end (the factory it installs), in a -DBUILD_SHARED_LIBS=ON
// build with hidden visibility (docs/library.md). A macro of its own because
// frame/ includes no api/ header (tests/layering.cmake).
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define M3G_FRAME_API __attribute__((visibility("default")))
#else
#define M3G_FRAME_API
#endif
