// --spectral hero (WF_SPECTRAL_HERO): the four wavelengths a path carries from its first
// dispersive vertex on (Wilkie et al. 2014; bsdf/dispersion.h), and what a dispersive vertex
// does to them. Included by wave/path_vertex.glsl after PathVertex and layersAt.
//
// State: v.lanes[j] = (share, lambda_j); lambda_j is 0 while the path is RGB. v.beta stays
// what reaches the film: the sum of the lanes' throughputs, each already weighted by
// dispersionWeight(lambda_j) / 4; share_j is lane j's part of it, per channel (the shares sum
// to 1 wherever v.beta is not 0). An RGB filter acts alike on every lane, so non-dispersive
// vertices, emission, next-event estimation and Russian roulette act on v.beta as without
// lanes, and leave the shares as they are.
//
// A dispersive vertex is one-sample MIS over the lanes (the balance heuristic): one lane
// samples the BSDF with its ior (lane 0 at the first vertex, where the four are a uniform
// rotation of the range so the hero is as good as a uniform pick; afterwards one drawn
// uniformly among the lanes that still carry something, dimension WF_DIM_HERO_LANE). The
// direction's density is the mean of those lanes' pdfs, and lane j's throughput is multiplied
// by f_j |cos| over that mean, next-event estimation weighing the same mean against the light.
// A Dirac reflection goes one way for every ior: each lane takes its own reflectance over the
// mean of the lanes' chances of that choice. A Dirac refraction bends each lane its own way:
// the lane that sampled it follows, its throughput over its chance (1 / lanes in the mixture
// of the choice's), and the others end (pbrt-v4's TerminateSecondary). Layered BSDFs (coat,
// sheen) end them at every Dirac event: their Dirac lobes are not separated here.

struct HeroVertex {
    bool on;      // the surface disperses (the path carries its lanes from here on)
    vec4 ior;     // each lane's ior
    vec4 mixture; // each lane's share of the sampling mixture: 1 / count, or 0
    uint lane;    // the lane that samples the BSDF
};

#if WF_BSDF_LAYERS
#define WF_HERO_LAYERS_PARAM , BsdfLayers layers
#define WF_HERO_LAYERS_ARG , layers
#define WF_HERO_EVAL(b, wo, wi) layeredEval(b, layers, wo, wi)
#define WF_HERO_PDF(b, wo, wi) layeredPdf(b, layers, wo, wi)
#else
#define WF_HERO_LAYERS_PARAM
#define WF_HERO_LAYERS_ARG
#define WF_HERO_EVAL(b, wo, wi) bsdfEval(b, wo, wi)
#define WF_HERO_PDF(b, wo, wi) bsdfPdf(b, wo, wi)
#endif

// part / total per channel, 0 where the total is.
vec3 heroShare(vec3 part, vec3 total) {
    return vec3(total.x > 0.0 ? part.x / total.x : 0.0, total.y > 0.0 ? part.y / total.y : 0.0,
                total.z > 0.0 ? part.z / total.z : 0.0);
}

// The path's lanes at its first dispersive vertex: the hero drawn as --spectral single draws
// its one wavelength, the others a quarter of the range on; v.beta takes their mean weight.
void heroStart(inout PathVertex v) {
    float hero = sampleWavelength(vertexSample1D(v, WF_DIM_WAVELENGTH));
    vec3 weights[WF_HERO_LANES];
    vec3 total = vec3(0.0);
    for (uint j = 0u; j < WF_HERO_LANES; ++j) {
        v.lanes[j].w = heroLaneWavelength(hero, j);
        weights[j] = dispersionWeight(v.lanes[j].w);
        total += weights[j];
    }
    for (uint j = 0u; j < WF_HERO_LANES; ++j)
        v.lanes[j].xyz = heroShare(weights[j], total);
    v.beta *= total * (1.0 / float(WF_HERO_LANES));
}

// The lanes at this vertex: whether it disperses, their iors, which lane samples.
HeroVertex heroAt(inout PathVertex v, SurfaceHit surface, float nd) {
    HeroVertex h;
    h.on = surface.dispersion > 0.0 && surface.transmission > 0.0;
    h.ior = vec4(nd);
    h.mixture = vec4(0.0);
    h.lane = 0u;
    if (!h.on)
        return h;
    bool first = v.lanes[0].w == 0.0;
    if (first)
        heroStart(v);
    uint alive = 0u;
    for (uint j = 0u; j < WF_HERO_LANES; ++j) {
        h.ior[j] = dispersionIor(nd, surface.dispersion, v.lanes[j].w);
        bool carries = first || any(greaterThan(v.lanes[j].xyz, vec3(0.0)));
        h.mixture[j] = carries ? 1.0 : 0.0;
        alive += carries ? 1u : 0u;
    }
    if (alive == 0u) { // nothing left to carry (v.beta is 0): lane 0, harmlessly
        h.mixture[0] = 1.0;
        return h;
    }
    h.mixture *= 1.0 / float(alive);
    if (!first) {
        int pick = int(min(uint(vertexSample1D(v, WF_DIM_HERO_LANE) * float(alive)), alive - 1u));
        for (uint j = 0u; j < WF_HERO_LANES; ++j) {
            if (h.mixture[j] > 0.0) {
                if (pick == 0)
                    h.lane = j;
                --pick;
            }
        }
    }
    return h;
}

// Every lane's f at wi (f[j]) and the mixture's density there; returns the lanes' f weighed
// by their shares, what multiplies v.beta.
vec3 heroEval(PathVertex v, HeroVertex h, BsdfParams bsdf WF_HERO_LAYERS_PARAM, vec3 wo,
              vec3 wi, out vec3 f[WF_HERO_LANES], out float pdf) {
    vec3 total = vec3(0.0);
    pdf = 0.0;
    for (uint j = 0u; j < WF_HERO_LANES; ++j) {
        f[j] = vec3(0.0);
        if (h.mixture[j] > 0.0) {
            BsdfParams b = bsdf;
            b.ior = h.ior[j];
            f[j] = WF_HERO_EVAL(b, wo, wi);
            pdf += h.mixture[j] * WF_HERO_PDF(b, wo, wi);
        }
        total += v.lanes[j].xyz * f[j];
    }
    return total;
}

// Lane j's throughput times g[j]: the shares follow; returns the factor of v.beta.
vec3 heroWeigh(inout PathVertex v, vec3 g[WF_HERO_LANES]) {
    vec3 total = vec3(0.0);
    for (uint j = 0u; j < WF_HERO_LANES; ++j) {
        g[j] *= v.lanes[j].xyz;
        total += g[j];
    }
    for (uint j = 0u; j < WF_HERO_LANES; ++j)
        v.lanes[j].xyz = heroShare(g[j], total);
    return total;
}

// A direction with a density: each lane's f |cos| over the mixture's pdf (which a guided
// vertex mixes further); returns the sample's weight.
vec3 heroScatter(inout PathVertex v, vec3 f[WF_HERO_LANES], float cosine, float pdf) {
    vec3 g[WF_HERO_LANES];
    for (uint j = 0u; j < WF_HERO_LANES; ++j)
        g[j] = pdf > 0.0 ? f[j] * (cosine / pdf) : vec3(0.0);
    return heroWeigh(v, g);
}

// A Dirac sample s drawn by lane h.lane, chosen with probability `branch` before the BSDF
// (a guided vertex's BSDF share, else 1); returns the sample's weight.
vec3 heroScatterDelta(inout PathVertex v, HeroVertex h, BsdfParams bsdf, vec3 wo, BsdfSample s,
                      float branch) {
    vec3 g[WF_HERO_LANES];
    for (uint j = 0u; j < WF_HERO_LANES; ++j)
        g[j] = vec3(0.0);
#if !WF_BSDF_LAYERS
    if (s.wi.z * wo.z > 0.0) {
        // A reflection: the same mirror direction for every ior.
        float chance = 0.0;
        for (uint j = 0u; j < WF_HERO_LANES; ++j) {
            BsdfParams b = bsdf;
            b.ior = h.ior[j];
            float probability;
            g[j] = bsdfDeltaReflection(b, wo, probability);
            chance += h.mixture[j] * probability;
        }
        for (uint j = 0u; j < WF_HERO_LANES; ++j)
            g[j] *= 1.0 / (chance * branch);
        return heroWeigh(v, g);
    }
#endif
    g[h.lane] = s.weight / h.mixture[h.lane];
    return heroWeigh(v, g);
}

// The BSDF's own sample s of lane h.lane, unguided: its weight and (with a density) its pdf
// become the lanes' (the mixture's).
void heroScatterSample(inout PathVertex v, HeroVertex h, BsdfParams bsdf WF_HERO_LAYERS_PARAM,
                       vec3 wo, inout BsdfSample s) {
    if (s.isDelta) {
        s.weight = heroScatterDelta(v, h, bsdf, wo, s, 1.0);
        return;
    }
    vec3 f[WF_HERO_LANES];
    heroEval(v, h, bsdf WF_HERO_LAYERS_ARG, wo, s.wi, f, s.pdf);
    s.weight = heroScatter(v, f, abs(s.wi.z), s.pdf);
}
