#version 450
layout(set = 0, binding = 0) uniform sampler2D uTexture;

layout(location = 0) in vec4 vColor;
layout(location = 1) in vec2 vUV;
layout(location = 0) out vec4 outColor;

void main() { outColor = vColor * texture(uTexture, vUV); }
