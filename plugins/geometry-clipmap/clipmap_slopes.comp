#version 450 core
// The slopes of a block of one level's height clipmap window, east and north, from central differences of the
// heights clipmap_fill.comp sampled (one-sided at the window's edges; a window spanning the turn wraps east and
// west), for a height layer that gives no slopes of its own (procedural relief): one sample of it a texel rather
// than five, the texels a texel apart, as far as the rings' vertices. Stored as rise per metre along the ground,
// which RG16F keeps to a thousandth for shading.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform readonly image2DArray heights;  // m
layout(rg16f, binding = 1) uniform writeonly image2DArray slopes;

uniform vec2 referenceLonlat;      // rad
uniform float radius;              // m
uniform int layer;                 // the window's layer of the textures
uniform ivec2 first;               // the block's first texel of the window
uniform ivec2 count;               // the block's texels
uniform ivec2 offset;              // where the window's texel 0 lies in its layer
uniform int texels;                // the window's width and height
uniform bool wholeTurn;            // the window spans every longitude: east and west wrap
uniform vec2 cornerFromReference;  // rad: the window's south-west corner from the reference
uniform vec2 texel;                // rad of longitude and latitude

float heightAt(ivec2 k) { return imageLoad(heights, ivec3((offset + k) % texels, layer)).r; }

void main() {
  ivec2 invocation = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(invocation, count))) return;
  ivec2 k = first + invocation;
  ivec2 west = ivec2(wholeTurn ? (k.x + texels - 1) % texels : max(k.x - 1, 0), k.y);
  ivec2 east = ivec2(wholeTurn ? (k.x + 1) % texels : min(k.x + 1, texels - 1), k.y);
  ivec2 south = ivec2(k.x, max(k.y - 1, 0)), north = ivec2(k.x, min(k.y + 1, texels - 1));
  float eastward = wholeTurn ? 2.0 : float(east.x - west.x);
  float latitude = referenceLonlat.y + cornerFromReference.y + (float(k.y) + 0.5) * texel.y;
  float eastRise = (heightAt(east) - heightAt(west)) / (eastward * texel.x * max(cos(latitude), 1e-4));
  float northRise = (heightAt(north) - heightAt(south)) / (float(north.y - south.y) * texel.y);
  imageStore(slopes, ivec3((offset + k) % texels, layer), vec4(vec2(eastRise, northRise) / radius, 0.0, 0.0));
}
