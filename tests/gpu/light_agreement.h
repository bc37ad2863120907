// The check behind the light-agreement tests: an estimator's image, from independent seeds,
// against the closed-form image block by block, with the images written out when it fails.
#pragma once
#include <string>

#include "light_rig.h"
#include "render/wavefront_renderer.h"

namespace wf::test {

struct AgreementMethod {
    const char* name;
    LightSampling lightSampling;
    bool solidAngle; // triangle and sphere sampling both: solid angle (else area)
    LightSelection selection = LightSelection::Auto;
};

struct AgreementOptions {
    uint32_t size = 32;  // image width and height
    uint32_t block = 4;  // compared regions: block x block pixels
    uint32_t spp = 64;
    int seeds = 4;
    // Compare only blocks where each pixel's samples are expected to hit a light at least this
    // often (BSDF sampling: rarer hits leave the spread over seeds no fair error estimate);
    // then no block at all may be compared.
    double minLightHits = 0.0;
};

// Renders `rig` at max depth 2 with `method` over independent seeds (`name` identifies the rig:
// its closed-form image is computed once) and expects every block's
// mean to lie within 5 standard errors (from the spread over seeds, pixel by pixel) plus 0.3%
// of the closed form. On failure writes NAME_METHOD_{actual,expected,ratio}.exr into the test
// output folder and reports a map of the blocks' ratios.
void expectAgreement(const std::string& name, const LightRig& rig, const AgreementMethod& method,
                     const AgreementOptions& options);

} // namespace wf::test
