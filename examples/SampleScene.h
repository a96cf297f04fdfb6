// The project's own sample scene, built in code: what `m3g sample` writes and
// what the README's main command renders. It exercises the common paths of a
// handset scene: a lit, textured, animated cube; a vertex-coloured unlit
// ground; a blended sprite; fog; a background colour; camera and lights.
#pragma once

#include <m3g/m3g.h>

namespace m3gcli {

/// A new World (active camera, lights, background, animation tracks).
m3g::Ref<m3g::World> buildSampleScene();

}  // namespace m3gcli
