#version 450 core
// One body's finished frame laid over the bodies behind it, in a scene of several (core/engine/src/scene_frame.cpp):
// its colour as the display shows it, and in alpha the share of the pixel the body covers (0 where none shows).

uniform sampler2D bodyFrame;

out vec4 colour;

void main() { colour = texelFetch(bodyFrame, ivec2(gl_FragCoord.xy), 0); }
