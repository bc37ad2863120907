// Reads of the path state. Each pass writes the state through the storage buffers of
// bindings.glsl and the next reads it through these storage texel views of the same memory,
// which lavapipe reads with one inlined gather instead of a loop over lanes (scene_tables.glsl).
// A pass may read an entry through its view and then overwrite it: an invocation only ever
// touches its own path's entries, and the barrier between passes makes writes visible (so the
// views are not `restrict`: they alias the storage buffers). The queues are read the same way:
// a storage-buffer load of one uint is a loop over the lanes too (+8% paths/s on the Cornell
// box for the three queue reads of intersect, shade and shadow).
layout(binding = WF_BINDING_RAY_ORIGIN_TEXELS, rgba32ui) uniform readonly uimageBuffer
    rayOriginTexels;
layout(binding = WF_BINDING_RAY_DIRECTION_TEXELS, rgba32ui) uniform readonly uimageBuffer
    rayDirectionTexels;
layout(binding = WF_BINDING_THROUGHPUT_TEXELS, rgba32ui) uniform readonly uimageBuffer
    throughputTexels;
layout(binding = WF_BINDING_RADIANCE_TEXELS, rgba32ui) uniform readonly uimageBuffer radianceTexels;
layout(binding = WF_BINDING_HITS_TEXELS, rgba32ui) uniform readonly uimageBuffer hitTexels;
layout(binding = WF_BINDING_RAY_QUEUE_TEXELS, r32ui) uniform readonly uimageBuffer rayQueueTexels;
#if WF_HAS_EMITTERS
layout(binding = WF_BINDING_SHADOW_ORIGIN_TEXELS, rgba32ui) uniform readonly uimageBuffer
    shadowOriginTexels;
layout(binding = WF_BINDING_SHADOW_DIRECTION_TEXELS, rgba32ui) uniform readonly uimageBuffer
    shadowDirectionTexels;
layout(binding = WF_BINDING_SHADOW_RADIANCE_TEXELS, rgba32ui) uniform readonly uimageBuffer
    shadowRadianceTexels;
#endif

// A macro, as GLSL functions cannot take the images themselves.
#define wfFloatTexel(view, path) uintBitsToFloat(imageLoad(view, int(path)))

vec4 rayOriginAt(uint path) { return wfFloatTexel(rayOriginTexels, path); }
vec4 rayDirectionAt(uint path) { return wfFloatTexel(rayDirectionTexels, path); }
vec4 throughputAt(uint path) { return wfFloatTexel(throughputTexels, path); }
vec4 radianceAt(uint path) { return wfFloatTexel(radianceTexels, path); }
// Entry `index` of the ray queue that depth `depth` reads (two halves, by depth parity).
uint rayQueueAt(uint depth, uint index) {
    return imageLoad(rayQueueTexels, int((depth & 1u) * params.pathCapacity + index)).x;
}
#if WF_SHADE_BINS > 1
layout(binding = WF_BINDING_KIND_QUEUE_TEXELS, r32ui) uniform readonly uimageBuffer kindQueueTexels;
// Entry `index` of shade bin `bin`: a slot of the current ray queue.
uint kindQueueAt(uint bin, uint index) {
    return imageLoad(kindQueueTexels, int(bin * params.pathCapacity + index)).x;
}
#endif
uvec4 hitAt(uint path) { return imageLoad(hitTexels, int(path)); }
#if WF_RAY_CONES
layout(binding = WF_BINDING_RAY_CONE_TEXELS, rg32ui) uniform readonly uimageBuffer rayConeTexels;
vec2 rayConeAt(uint path) { return uintBitsToFloat(imageLoad(rayConeTexels, int(path)).xy); }
#endif
#if WF_HAS_EMITTERS
// xyz: the connection's origin as float bits, w: its path.
uvec4 shadowOriginAt(uint slot) { return imageLoad(shadowOriginTexels, int(slot)); }
vec4 shadowDirectionAt(uint slot) { return wfFloatTexel(shadowDirectionTexels, slot); }
vec4 shadowRadianceAt(uint slot) { return wfFloatTexel(shadowRadianceTexels, slot); }
#endif
