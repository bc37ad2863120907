// Which pixel and sample a path of the current wave traces (see PassConstants in
// render_types.h). Raygen, shade, accumulate and the megakernel all map paths through these,
// so a wave of any shape traces the same samples.
#ifndef WF_WAVE_PATHS_GLSL
#define WF_WAVE_PATHS_GLSL

// The wave's `local`-th pixel: with WF_ADAPTIVE an entry of the active-pixel list (the pixels
// whose sample allocation reaches this round), else the image's pixels in order.
uint wavePixel(PassConstants wave, uint local) {
#if WF_ADAPTIVE
    return activePixels[wave.pixelBase + local];
#else
    return wave.pixelBase + local;
#endif
}

uint wavePathPixel(PassConstants wave, uint path) {
    return wavePixel(wave, path % wave.wavePixels);
}

uint wavePathSample(PassConstants wave, uint path) {
    return wave.sampleBase + path / wave.wavePixels;
}

#endif
