#version 460
// light_splat (--integrator light): the visibility of each camera connection light_shade
// queued, and the splat of the visible ones into the light film (bidir/light_film.glsl).
// In: the shadow queue (count in counters.shadowArgs.count): shadowOrigin (with the light film
// entry in w), shadowDirection (the segment: to the lens point, or with BDPT a camera vertex's
// NEE or connection), shadowRadiance (the value).
// Out: lightFilm[entry] += value when the segment t in (0, 1) is unoccluded; a value that is
// not finite or over WF_LIGHT_FILM_MAX is dropped and counted in counters.nonFiniteSamples.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#if !WF_HAS_EMITTERS || WF_INTEGRATOR == WF_INTEGRATOR_PATH
#error "light_splat exists only for light tracing in scenes with emitters"
#endif
#include "traversal/scene_intersect.glsl"
#include "bidir/light_film.glsl"

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.shadowArgs.count)
        return;
    uvec4 origin = shadowOriginAt(index);
    vec4 radianceAndTime = shadowRadianceAt(index);
    vec3 value = radianceAndTime.rgb;
#if WF_MOTION
    wfRayTime = radianceAndTime.w; // the connection's path's time (light_shade, shade)
#endif
    // Written as a test that NaN fails, so that no fast-math folding can let one through.
    bool storable = all(greaterThanEqual(value, vec3(0.0))) &&
                    all(lessThanEqual(value, vec3(WF_LIGHT_FILM_MAX)));
    if (!storable) {
        atomicAdd(counters.nonFiniteSamples, 1u);
        return;
    }
    // A BDPT camera vertex's NEE may end on a sphere light, which its test leaves out (w: 1 +
    // that light, as shadow.comp reads it); connections end on no light (w = 0).
    vec4 segment = shadowDirectionAt(index);
    if (!segmentOccluded(uintBitsToFloat(origin.xyz), segment.xyz, uint(segment.w) - 1u))
        lightFilmAdd(origin.w, value);
}
