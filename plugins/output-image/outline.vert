#version 450 core
// The triangle fan of the body's outline (body_outline.hpp), given in clip space.
layout(location = 0) in vec4 clipPosition;

void main() { gl_Position = clipPosition; }
