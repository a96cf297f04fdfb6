// The project's own sample scene, built in code: what `m3g sample` writes and
// what the README's main command renders. It exercises the common paths of a
// handset scene: a lit, textured, animated cube; a vertex-coloured unlit
// ground; a blended sprite; fog; a background colour; camera and lights.
#pragma once

#include <m3g/m3g.h>

namespace m3gcli {

/// A new World (active camera, lights, background, animation tracks).
m3g::Ref<m3g::World> buildSampleScene();

/// A cube of side 2 centred on the origin (positions as shorts scaled by
/// 1/64), normals per face, texture coordinates 0..1 per face, six strips
/// of four vertices, using `appearance`. Also used by the game example.
m3g::Ref<m3g::Mesh> makeCube(m3g::Appearance* appearance);

/// A flat 8x8 ground grid at y = -1.2 from -4 to 4 in x and z, vertex
/// coloured in two greens, unlit, flat shaded, no culling.
m3g::Ref<m3g::Mesh> makeGround();

}  // namespace m3gcli
