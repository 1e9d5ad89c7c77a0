#version 450 core
// One body's finished frame laid over the bodies behind it, in a scene of several (core/engine/src/scene_frame.cpp):
// its colour as the display shows it times the share of the pixel the body covers, that share in alpha (0 where none
// shows), and the light its air adds beyond its edge.

uniform sampler2D bodyFrame;

out vec4 colour;

void main() { colour = texelFetch(bodyFrame, ivec2(gl_FragCoord.xy), 0); }
