#version 460
// The closest sphere light: the record intersect.comp writes, (t, -, -, WF_SPHERE_HIT | light).
#extension GL_EXT_ray_tracing : require

layout(location = 0) rayPayloadInEXT uvec4 hit;

void main() {
    hit = uvec4(floatBitsToUint(gl_HitTEXT), 0u, 0u, 0x80000000u | uint(gl_PrimitiveID));
}
