// Four SQUAD samples side by side in SSE lanes (KeyframeSampler's
// sampleSquads). Internal to m3g_scene.
#pragma once

#include "KeyframeSampler.h"

namespace m3g::detail {

/// Computes the samples of `lanes` (1..4 of them, `count`) whose inner
/// arcs (key and control) are Circle or Linear and whose outer arc, between
/// the two inner points, is a Circle, writing their quaternions, and
/// returns the mask of those written (bit i: lane i). The rest (a
/// Renormalise inner arc, an outer arc that is not a circle) are left to
/// the caller's one-at-a-time path.
/// Each lane does Slerp.h's operations in Slerp.h's order, without fused
/// multiply-adds, so a written sample has the bits of
/// arcAt(k, arcOf(k, c), 2u(1 - u)) with k and c the inner SLERPs' points
/// computed the same way. Without SSE2 (not x86-64): returns 0.
unsigned squadLanes(const SquadSample* const* lanes, int count) noexcept;

}  // namespace m3g::detail
