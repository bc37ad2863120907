// The light subpaths of a sample index as the passes see them (bidir/light_share.h):
// params.lightPaths of them, in the path slots whose pixel index is below it.
#ifndef WF_LIGHT_SHARE_GLSL
#define WF_LIGHT_SHARE_GLSL
#include "bidir/light_share.h"

uint lightSubpathOfPixel(uint pixel) {
    return lightSubpathOfPixel(pixel, params.pixelCount, params.lightPaths);
}

bool tracesLightSubpath(uint pixel) { return pixel < params.lightPaths; }

// What a light subpath's camera splat carries beyond one subpath per pixel: W H / lightPaths.
float lightShareSplatScale() { return float(params.pixelCount) / float(params.lightPaths); }

#endif
