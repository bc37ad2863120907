#version 460
// The closest triangle: the record intersect.comp writes, (t, b1, b2, triangle), or in
// two-level scenes (instance, b1, b2, triangle). The instance's custom index is its mesh's
// first triangle in the scene's table, so the triangle index is the table's own; (b1, b2) are
// the driver's barycentrics of p1 and p2 (vertices are given in the table's order), from which
// shade recomputes the hit point and its error bound, so spawned rays are offset as after the
// BVH's own intersection (pbrt-v4 does the same with OptiX).
#extension GL_EXT_ray_tracing : require

layout(location = 0) rayPayloadInEXT uvec4 hit;
hitAttributeEXT vec2 barycentrics;

void main() {
#if WF_HAS_INSTANCES
    uint first = uint(gl_InstanceID);
#else
    uint first = floatBitsToUint(gl_HitTEXT);
#endif
    hit = uvec4(first, floatBitsToUint(barycentrics.x), floatBitsToUint(barycentrics.y),
                uint(gl_InstanceCustomIndexEXT + gl_PrimitiveID));
}
