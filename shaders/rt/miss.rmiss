#version 460
// The ray met nothing: the payload becomes intersect.comp's miss record (w = WF_MISS), which
// the shadow pass reads as "unoccluded".
#extension GL_EXT_ray_tracing : require

layout(location = 0) rayPayloadInEXT uvec4 hit;

void main() { hit = uvec4(0u, 0u, 0u, 0xffffffffu); }
