// Which pixel and sample a path of the current wave traces (see PassConstants in
// render_types.h). Raygen, shade, accumulate and the megakernel all map paths through these,
// so a wave of any shape traces the same samples.
#ifndef WF_WAVE_PATHS_GLSL
#define WF_WAVE_PATHS_GLSL

uint wavePathPixel(PassConstants wave, uint path) {
    return wave.pixelBase + path % wave.wavePixels;
}

uint wavePathSample(PassConstants wave, uint path) {
    return wave.sampleBase + path / wave.wavePixels;
}

#endif
