// The BSDF's local frame at a hit, built here for every integrator: the path tracer's vertices
// (path_vertex.glsl), light subpaths' (light_shade.comp) and BDPT's light vertices
// (bdpt_connect.glsl) must evaluate one BSDF, and an anisotropic one depends on the frame's
// x axis, not only on +z. Included by path_vertex.glsl after surface.glsl and the BSDF.
#ifndef WF_SHADING_FRAME_GLSL
#define WF_SHADING_FRAME_GLSL

struct ShadingFrame {
    bool flip;      // +z is -ns: a transmissive surface seen from inside
    vec3 n;         // +z: the shading normal on the BSDF's outside
    vec3 tangent;   // +x: with anisotropy, the material's direction (bsdf/anisotropy.h)
    vec3 bitangent; // +y = n x tangent
    vec3 outside;   // the geometric normal on +z's side, for ray offsets
};

// Opaque surfaces shade two-sided (ns already faces the arriving ray); transmissive ones keep
// +z on the outside so that the BSDF knows which medium the ray is in.
ShadingFrame shadingFrameAt(SurfaceHit surface) {
    ShadingFrame f;
    f.flip = surface.transmission > 0.0 && !surface.frontFace;
    f.n = f.flip ? -surface.ns : surface.ns;
    f.outside = f.flip ? -surface.ng : surface.ng;
    buildOrthonormalBasis(f.n, f.tangent, f.bitangent);
#if WF_HAS_ANISOTROPY
    // The anisotropic lobes stretch along the frame's x axis: the material's direction, made
    // orthogonal to the shading normal. Arbitrary (as above) where the surface is isotropic.
    vec3 stretch = surface.anisotropyDirection - f.n * dot(f.n, surface.anisotropyDirection);
    if (surface.anisotropy > 0.0 && dot(stretch, stretch) > 1e-12) {
        f.tangent = normalize(stretch);
        f.bitangent = cross(f.n, f.tangent);
    }
#endif
    return f;
}

vec3 toShadingFrame(ShadingFrame f, vec3 w) {
    return vec3(dot(w, f.tangent), dot(w, f.bitangent), dot(w, f.n));
}

vec3 fromShadingFrame(ShadingFrame f, vec3 w) {
    return normalize(f.tangent * w.x + f.bitangent * w.y + f.n * w.z);
}

#if WF_BSDF_LAYERS && WF_HAS_CLEARCOAT && WF_HAS_CLEARCOAT_NORMAL_MAPS
// The coat's own normal in the frame (flipped with it); (0, 0, 1) exactly, as layersAt leaves
// it, without one.
void placeCoatNormal(inout BsdfLayers layers, SurfaceHit surface, ShadingFrame f) {
    if (surface.coatNormal != surface.ns)
        layers.coatNormal = toShadingFrame(f, f.flip ? -surface.coatNormal : surface.coatNormal);
}
#endif

#endif
