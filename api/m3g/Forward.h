// Forward declarations of every public M3G class.
#pragma once

namespace m3g {
class AnimationController;
class AnimationTrack;
class Appearance;
class Background;
class Camera;
class CompositingMode;
class Fog;
class Graphics;
class Graphics3D;
class Group;
class Image2D;
class IndexBuffer;
class KeyframeSequence;
class Light;
class Loader;
class Material;
class Mesh;
class MorphingMesh;
class Node;
class Object3D;
class PolygonMode;
class RayIntersection;
class SkinnedMesh;
class Sprite3D;
class Texture2D;
class Transform;
class Transformable;
class TriangleStripArray;
class VertexArray;
class VertexBuffer;
class World;
}  // namespace m3g
