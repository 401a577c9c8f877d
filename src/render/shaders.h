#pragma once
// GLSL 3.30 core sources of the renderer's five programs.

namespace physltl::render::shaders {

// Bodies, in world coordinates: one directional light plus a sky/ground ambient term.
inline constexpr const char* kLitVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 vertex_color;
uniform mat4 view_projection;
out vec3 world_normal;
out vec4 color;
void main() {
  world_normal = normal;
  color = vertex_color;
  gl_Position = view_projection * vec4(position, 1.0);
})";

inline constexpr const char* kLitFragment = R"(#version 330 core
in vec3 world_normal;
in vec4 color;
uniform vec3 towards_light;
out vec4 fragment;
void main() {
  vec3 n = normalize(world_normal);
  float sky = 0.5 + 0.5 * n.z;  // faces turned up see more sky
  float light = 0.35 + 0.25 * sky + 0.5 * max(dot(n, towards_light), 0.0);
  fragment = vec4(min(color.rgb * light, vec3(1.0)), color.a);
})";

// Floor paint, lines, panels: positions already in the space `transform` maps from (world or pixels).
inline constexpr const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 vertex_color;
uniform mat4 transform;
out vec4 color;
void main() {
  color = vertex_color;
  gl_Position = transform * vec4(position, 1.0);
})";

inline constexpr const char* kFlatFragment = R"(#version 330 core
in vec4 color;
out vec4 fragment;
void main() { fragment = color; })";

// Soft drop shadows: a rounded rectangle (box footprint, or a disc when half extents are 0) given in the
// body's frame, its darkness fading across `shape.w` metres around the edge.
inline constexpr const char* kShadowVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 body_frame_position;
layout(location = 2) in vec4 shape_in;     // half extent x, half extent y, corner radius, softness
layout(location = 3) in float strength_in;
uniform mat4 transform;
out vec2 local;
out vec4 shape;
out float strength;
void main() {
  local = body_frame_position;
  shape = shape_in;
  strength = strength_in;
  gl_Position = transform * vec4(position, 1.0);
})";

inline constexpr const char* kShadowFragment = R"(#version 330 core
in vec2 local;
in vec4 shape;
in float strength;
out vec4 fragment;
void main() {
  vec2 q = abs(local) - shape.xy;
  float distance = length(max(q, 0.0)) + min(max(q.x, q.y), 0.0) - shape.z;
  fragment = vec4(0.0, 0.0, 0.0, strength * (1.0 - smoothstep(-shape.w, shape.w, distance)));
})";

// Text: glyph coverage from the font atlas, in pixel coordinates.
inline constexpr const char* kTextVertex = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 atlas_position;
uniform mat4 transform;
out vec2 uv;
void main() {
  uv = atlas_position;
  gl_Position = transform * vec4(position, 0.0, 1.0);
})";

inline constexpr const char* kTextFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D atlas;
uniform vec4 color;
out vec4 fragment;
void main() { fragment = vec4(color.rgb, color.a * texture(atlas, uv).r); })";

// A layer drawn with its colours premultiplied by alpha, laid over the frame pixel for pixel.
inline constexpr const char* kLayerVertex = R"(#version 330 core
layout(location = 0) in vec2 corner;  // of the whole frame, -1..1
out vec2 uv;
void main() {
  uv = 0.5 * corner + 0.5;
  gl_Position = vec4(corner, 0.0, 1.0);
})";

inline constexpr const char* kLayerFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D layer;
out vec4 fragment;
void main() { fragment = texture(layer, uv); })";

}  // namespace physltl::render::shaders
