#version 460
// accumulate: adds the wave's samples of each pixel to the film one at a time, in sample
// order, so the film's bits do not depend on how samples were grouped into waves (a wave may
// hold several samples of every pixel, or one sample of a range of pixels). A sample with a
// NaN or Inf component is dropped (zeroed) and counted; the test is on the bit pattern so
// that no fast-math pass can fold it away.
// In: radiance of the wave's paths (with --aov, their first hits too). Out: film[pixel]
// (with --aov, aovFilm[2 pixel ..]; with WF_SECOND_MOMENT, momentFilm[pixel]: the sums of
// squares and the largest component of any sample, which render/error_estimate.h reads),
// with WF_ERROR_REPLICATES, replicateFilm: the sums and counts of each replicate's samples but
// the first, from which the film's error is estimated for correlated samplers),
// counters.nonFiniteSamples.
// --integrator light: a sample is the camera's value plus its light film entry (the splats of
// every light subpath of its sample index into this pixel), which is read and zeroed here.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#include "wave/wave_paths.glsl"
#if WF_GUIDING
#include "guiding/guide_bindings.glsl"
#include "guiding/guide_path.glsl"
#endif
#if WF_INTEGRATOR != WF_INTEGRATOR_PATH && WF_HAS_EMITTERS
#include "bidir/light_film.glsl"
#endif

layout(push_constant) uniform Push { PassConstants pass; };

bool isFiniteBits(vec3 v) {
    uvec3 exponent = floatBitsToUint(v) & uvec3(0x7f800000u);
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

void main() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= pass.wavePixels)
        return;
    uint pixel = wavePixel(pass, local);
    vec4 sum = film[pixel];
#if WF_AOV
    vec4 firstHit = aovFilm[2u * pixel];
    vec4 normal = aovFilm[2u * pixel + 1u];
#endif
#if WF_SECOND_MOMENT
    vec4 squares = momentFilm[pixel];
#endif
#if defined(WF_ERROR_REPLICATES) && WF_ERROR_REPLICATES > 1
    const uint others = uint(WF_ERROR_REPLICATES) - 1u;
    vec4 replicates[WF_ERROR_REPLICATES - 1];
    for (uint r = 0u; r < others; ++r)
        replicates[r] = replicateFilm[pixel * others + r];
#endif
    uint dropped = 0u;
    for (uint s = 0u; s < pass.samplesPerPixel; ++s) {
        uint path = local + s * pass.wavePixels;
        vec3 value = radianceAt(path).rgb;
#if WF_INTEGRATOR != WF_INTEGRATOR_PATH && WF_HAS_EMITTERS
        value += lightFilmTake(path); // waves of light tracing cover the image: path = entry
#endif
        bool finite = isFiniteBits(value);
#if defined(WF_ERROR_REPLICATES) && WF_ERROR_REPLICATES > 1
        uint replicate = (pass.sampleBase + s) % uint(WF_ERROR_REPLICATES);
        if (replicate > 0u) // a dropped sample counts as zero in its replicate, as in the film
            replicates[replicate - 1u] += vec4(finite ? value : vec3(0.0), 1.0);
#endif
        if (finite) {
            sum.rgb += value;
#if WF_GUIDING
            guideSplatPath(path, value); // the path is done: credit its guided vertices
#endif
#if WF_SECOND_MOMENT
            squares.rgb += value * value;
            squares.a = max(squares.a, max(value.r, max(value.g, value.b)));
#endif
        } else {
            ++dropped;
        }
#if WF_AOV
        firstHit += aovPath[2u * path];
        normal += aovPath[2u * path + 1u];
#endif
    }
#if WF_AOV
    aovFilm[2u * pixel] = firstHit;
    aovFilm[2u * pixel + 1u] = normal;
#endif
#if WF_SECOND_MOMENT
    momentFilm[pixel] = squares;
#endif
#if defined(WF_ERROR_REPLICATES) && WF_ERROR_REPLICATES > 1
    for (uint r = 0u; r < others; ++r)
        replicateFilm[pixel * others + r] = replicates[r];
#endif
    if (dropped > 0u)
        atomicAdd(counters.nonFiniteSamples, dropped);
    film[pixel] = vec4(sum.rgb, sum.a + float(pass.samplesPerPixel));
}
