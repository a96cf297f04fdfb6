#version 450
// The viewer's UI (Dear ImGui draw lists) over a window frame: positions in
// pixels, mapped to clip space by a push-constant scale and offset.
layout(location = 0) in vec2 aPos;
layout(location = 1) in vec2 aUV;
layout(location = 2) in vec4 aColor;  // R8G8B8A8_UNORM

layout(push_constant) uniform Screen {
    vec2 scale;
    vec2 translate;
} screen;

layout(location = 0) out vec4 vColor;
layout(location = 1) out vec2 vUV;

void main() {
    vColor = aColor;
    vUV = aUV;
    gl_Position = vec4(aPos * screen.scale + screen.translate, 0.0, 1.0);
}
