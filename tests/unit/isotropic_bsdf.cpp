// bsdf.h without WF_HAS_ANISOTROPY and WF_HAS_DIFFUSE_TRANSMISSION (see isotropic_bsdf.h). It
// is included inside a namespace of its own, so that its inline functions and structs, which
// differ from the full build's of the same names, are other entities (one definition per
// program). What it includes and does not depend on the switches (microfacet.h,
// iridescence.h) is included first, as usual.
#include "tests/unit/isotropic_bsdf.h"

#include "shaders/bsdf/iridescence.h"
#include "shaders/bsdf/microfacet.h"

#define WF_HAS_ANISOTROPY 0
#define WF_HAS_DIFFUSE_TRANSMISSION 0
namespace wf::test::isotropic_build {
using namespace ::wf::gpu_types;
#include "shaders/bsdf/bsdf.h"
} // namespace wf::test::isotropic_build

namespace wf::test {
namespace {

isotropic_build::wf::gpu_types::BsdfParams params(const PlainMaterial& m) {
    isotropic_build::wf::gpu_types::BsdfParams p{};
    p.baseColor = m.baseColor;
    p.metallic = m.metallic;
    p.roughness = m.roughness;
    p.ior = m.ior;
    p.transmission = m.transmission;
    p.specular = m.specular;
    p.specularColor = m.specularColor;
    return p;
}

} // namespace

glm::vec3 isotropicEval(const PlainMaterial& m, glm::vec3 wo, glm::vec3 wi) {
    return isotropic_build::wf::gpu_types::bsdfEval(params(m), wo, wi);
}

float isotropicPdf(const PlainMaterial& m, glm::vec3 wo, glm::vec3 wi) {
    return isotropic_build::wf::gpu_types::bsdfPdf(params(m), wo, wi);
}

PlainSample isotropicSample(const PlainMaterial& m, glm::vec3 wo, float uLobe, glm::vec2 u) {
    isotropic_build::wf::gpu_types::BsdfSample s;
    const bool sampled = isotropic_build::wf::gpu_types::bsdfSample(params(m), wo, uLobe, u, s);
    return {sampled, s.wi, s.pdf, s.weight, s.isDelta, s.eta};
}

bool isotropicHasNonDelta(const PlainMaterial& m) {
    return isotropic_build::wf::gpu_types::bsdfHasNonDelta(params(m));
}

} // namespace wf::test
