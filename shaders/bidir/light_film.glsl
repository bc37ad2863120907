// The light film (--integrator light): per entry (a pixel in a sample slot of the wave), the
// sum of the light subpaths' splats as 64-bit unsigned fixed point with 32 fractional bits,
// in two words per channel (low, high). Integer adds commute exactly, so the same seed gives
// the same image bit for bit whatever order the splats arrive in; float atomics would not.
// A splat is at most WF_LIGHT_FILM_MAX (the caller drops and counts larger ones as it drops
// NaN), so a high word of 2^32 - 1 holds 256 of the largest in one entry; values below 2^-33
// round to 0. accumulate.comp reads each entry once per wave and zeroes it.
#ifndef WF_LIGHT_FILM_GLSL
#define WF_LIGHT_FILM_GLSL

#define WF_LIGHT_FILM_MAX 16777216.0 // 2^24

layout(std430, binding = WF_BINDING_LIGHT_FILM) buffer LightFilmBuffer {
    uint lightFilm[]; // 6 words per entry: r low, r high, g low, g high, b low, b high
};

// value in [0, 2^24): its whole part, and its fraction in 2^32 ulps rounded to nearest (the
// fraction has at least 8 exact bits below the point).
uvec2 lightFilmFixed(float value) {
    uint high = uint(value);
    float fraction = (value - float(high)) * 4294967296.0;
    return uvec2(fraction >= 4294967295.0 ? 4294967295u : uint(fraction + 0.5), high);
}

void lightFilmAddChannel(uint word, uvec2 fixedValue) {
    uint high = fixedValue.y;
    if (fixedValue.x != 0u) {
        uint old = atomicAdd(lightFilm[word], fixedValue.x);
        if (old + fixedValue.x < old)
            high += 1u;
    }
    if (high != 0u)
        atomicAdd(lightFilm[word + 1u], high);
}

// value: finite, each channel in [0, WF_LIGHT_FILM_MAX].
void lightFilmAdd(uint entry, vec3 value) {
    lightFilmAddChannel(6u * entry, lightFilmFixed(value.r));
    lightFilmAddChannel(6u * entry + 2u, lightFilmFixed(value.g));
    lightFilmAddChannel(6u * entry + 4u, lightFilmFixed(value.b));
}

// A sum kept in a shader's registers in the film's fixed point, so that terms found in any
// order (vertex merging's grid lists) sum to the same bits. Its high words wrap past 2^32.
struct LightFilmSum {
    uvec3 low;
    uvec3 high;
};

LightFilmSum lightFilmSumZero() { return LightFilmSum(uvec3(0u), uvec3(0u)); }

void lightFilmSumAdd(inout LightFilmSum sum, vec3 value) {
    for (int c = 0; c < 3; ++c) {
        uvec2 v = lightFilmFixed(value[c]);
        uint low = sum.low[c] + v.x;
        sum.high[c] += v.y + (low < v.x ? 1u : 0u);
        sum.low[c] = low;
    }
}

void lightFilmAddSum(uint entry, LightFilmSum sum) {
    for (uint c = 0u; c < 3u; ++c)
        lightFilmAddChannel(6u * entry + 2u * c, uvec2(sum.low[c], sum.high[c]));
}

// The entry's sum, and zeroes it for the next wave.
vec3 lightFilmTake(uint entry) {
    vec3 sum;
    for (uint c = 0u; c < 3u; ++c) {
        uint word = 6u * entry + 2u * c;
        sum[c] = float(lightFilm[word + 1u]) + float(lightFilm[word]) * (1.0 / 4294967296.0);
        lightFilm[word] = 0u;
        lightFilm[word + 1u] = 0u;
    }
    return sum;
}

#endif
