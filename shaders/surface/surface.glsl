// What shading needs to know about a hit point, gathered in one place: position with its
// error bound for spawning rays, geometric and shading normals, and the material's values at
// that point. Texture lookups and interpolated normals (when a scene has them) live here, so
// shade.comp stays about light transport. Per-scene switches (texture_types.h): WF_HAS_NORMALS
// interpolates vertex normals, WF_HAS_NORMAL_MAPS perturbs them with the normal texture,
// WF_HAS_TEXTURES multiplies the factors by their textures (glTF metallic-roughness: B is
// metalness, G roughness; colour textures are sRGB-decoded in textures.glsl), and
// WF_HAS_SPECULAR_TEXTURES the KHR_materials_specular maps. WF_HAS_CLEARCOAT, WF_HAS_SHEEN and
// WF_HAS_VOLUME carry those extensions' factors, and WF_HAS_CLEARCOAT_TEXTURES,
// _CLEARCOAT_NORMAL_MAPS, _SHEEN_TEXTURES and _THICKNESS_TEXTURES their textures;
// WF_HAS_DIFFUSE_TRANSMISSION carries that extension's factors and textures, WF_HAS_DISPERSION
// KHR_materials_dispersion's 20 / Abbe number.
#include "surface/textures.glsl"

struct SurfaceHit {
    vec3 p;          // hit point from barycentrics
    vec3 pError;     // conservative bound for offsetRayOrigin
    vec3 ng;         // unit geometric normal, facing the side the ray arrived from
    vec3 ns;         // unit shading normal, same side as ng
    bool frontFace;  // the ray hit the counter-clockwise side
    float area;      // triangle area, for the emitter pdf
    uint material;
    uint emitter;    // WF_NO_EMITTER unless the triangle is in the light table
    vec3 baseColor;  // baseColorFactor x baseColorTexture (linear)
    float alpha;     // the same product's alpha (cut-outs are already applied by traversal)
    float metallic;
    float roughness;
    float ior;
    float transmission;
    float specular;
    vec3 specularColor;
    vec3 emission;   // already zero for faces that do not emit
#if WF_HAS_CLEARCOAT
    float clearcoat;
    float clearcoatRoughness;
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    vec3 coatNormal; // unit, same side as ng: the coat's own normal map, else equal to ns
#endif
#endif
#if WF_HAS_SHEEN
    vec3 sheenColor;
    float sheenRoughness;
#endif
#if WF_HAS_VOLUME
    vec3 absorption; // sigma_a behind the surface (KHR_materials_volume); zero if thin-walled
#endif
#if WF_HAS_IRIDESCENCE
    float iridescence;          // KHR_materials_iridescence factor x texture R
    float iridescenceIor;
    float iridescenceThickness; // nm: mix(minimum, maximum, texture G), or maximum
#endif
#if WF_HAS_ANISOTROPY
    float anisotropy;             // KHR_materials_anisotropy strength x texture B
    vec3 anisotropyDirection;     // world, in the surface's tangent plane; zero: none
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION
    float diffuseTransmission;     // KHR_materials_diffuse_transmission factor x texture A
    vec3 diffuseTransmissionColor; // colour factor x texture RGB (sRGB)
#endif
#if WF_HAS_DISPERSION
    float dispersion; // KHR_materials_dispersion: 20 / Abbe number; 0: none
#endif
};

// Whether light crosses the surface (KHR_materials_transmission, _diffuse_transmission): its
// mesh has an inside, which absorbs (KHR_materials_volume), and lights on both sides reach it.
bool surfaceTransmits(SurfaceHit s) {
#if WF_HAS_DIFFUSE_TRANSMISSION
    return s.transmission > 0.0 || s.diffuseTransmission > 0.0;
#else
    return s.transmission > 0.0;
#endif
}

vec3 decodeUnit(uint packed) { return octDecode(unpackSnorm2x16(packed)); }

// Two-level scenes keep instanced meshes in their own space (vertex attributes included): the
// hit's instance maps them to world space here, normals by the inverse transpose. One-level
// scenes are in world space already and pass an unused instance.
vec3 normalToWorld(Instance instance, vec3 n) {
#if WF_HAS_INSTANCES
    vec3 world = vec3(instance.objectFromWorld0) * n.x + vec3(instance.objectFromWorld1) * n.y +
                 vec3(instance.objectFromWorld2) * n.z;
    float len = length(world);
    return len > 0.0 ? world / len : n;
#else
    return n;
#endif
}

vec3 vectorToWorld(Instance instance, vec3 v) {
#if WF_HAS_INSTANCES
    return affineVector(instance.worldFromObject0, instance.worldFromObject1,
                        instance.worldFromObject2, v);
#else
    return v;
#endif
}

bool instanceMirrors(Instance instance) {
#if WF_HAS_INSTANCES
    return (instance.flags & WF_INSTANCE_MIRRORED) != 0u;
#else
    return false;
#endif
}

// A shading lookup of reference `ref` at the hit: filtered by the ray cone's footprint where
// the variant has ray cones (textures.glsl), else level 0.
#if WF_HAS_TEXTURES
vec4 surfaceTexture(uint ref, uint triangleIndex, float b1, float b2, float footprint) {
#if WF_RAY_CONES
    return sampleTriangleTextureCone(ref, triangleIndex, b1, b2, footprint);
#else
    return sampleTriangleTexture(ref, triangleIndex, b1, b2);
#endif
}
#endif

// The interpolated vertex normal on the front (counter-clockwise) side, or ng where the data
// would give a zero or non-finite vector.
vec3 interpolatedNormal(Instance instance, uint triangleIndex, float b1, float b2, vec3 ng) {
    vec3 n = ng;
#if WF_HAS_NORMALS
    TriangleNormals corners = triangleNormalsAt(triangleIndex);
    float b0 = 1.0 - b1 - b2;
    vec3 sum = b0 * normalToWorld(instance, decodeUnit(corners.n0)) +
               b1 * normalToWorld(instance, decodeUnit(corners.n1)) +
               b2 * normalToWorld(instance, decodeUnit(corners.n2));
    float len = length(sum);
    n = len > 1e-6 ? sum / len : ng;
#endif
    return n;
}

#if WF_HAS_NORMAL_MAPS
// n perturbed by a tangent-space normal map (`texture`, its xy scaled by `scale`) in the
// triangle's tangent frame; n itself where that frame or the result degenerates.
vec3 normalMapped(Instance instance, uint triangleIndex, uint texture, float scale, float b1,
                  float b2, vec3 n, float footprint) {
    TriangleTangents frame = triangleTangentsAt(triangleIndex);
    vec3 t = vectorToWorld(instance, (1.0 - b1 - b2) * decodeUnit(frame.t0) +
                                         b1 * decodeUnit(frame.t1) + b2 * decodeUnit(frame.t2));
    t -= n * dot(n, t); // Gram-Schmidt against the interpolated normal
    float tLen = length(t);
    if (tLen > 1e-6) {
        t /= tLen;
        // A mirroring instance turns the frame's handedness (as the loader does when it
        // flattens a mirrored mesh).
        bool flipped = ((frame.signs & 1u) != 0u) != instanceMirrors(instance);
        vec3 b = cross(n, t) * (flipped ? -1.0 : 1.0);
        vec3 m = surfaceTexture(texture, triangleIndex, b1, b2, footprint).xyz;
        m = m * 2.0 - 1.0;
        m.xy *= scale;
        vec3 mapped = t * m.x + b * m.y + n * m.z;
        float mLen = length(mapped);
        n = mLen > 1e-6 ? mapped / mLen : n;
    }
    return n;
}
#endif

// The shading normal on the front side: interpolated vertex normals, then the normal map.
vec3 frontShadingNormal(Instance instance, uint triangleIndex, Material material, float b1,
                        float b2, vec3 ng, float footprint) {
    vec3 n = interpolatedNormal(instance, triangleIndex, b1, b2, ng);
#if WF_HAS_NORMAL_MAPS
    if (material.normalTexture != WF_NO_TEXTURE)
        n = normalMapped(instance, triangleIndex, material.normalTexture, material.normalScale,
                         b1, b2, n, footprint);
#endif
    return n;
}

#if WF_HAS_CLEARCOAT_NORMAL_MAPS
// KHR_materials_clearcoat's clearcoatNormalTexture on the front side: the interpolated vertex
// normal perturbed by the coat's own map (the base's normal map does not reach the coat).
vec3 frontCoatNormal(Instance instance, uint triangleIndex, Material material, float b1,
                     float b2, vec3 ng, float footprint) {
    vec3 n = interpolatedNormal(instance, triangleIndex, b1, b2, ng);
#if WF_HAS_NORMAL_MAPS
    n = normalMapped(instance, triangleIndex, material.clearcoatNormalTexture,
                     material.clearcoatNormalScale, b1, b2, n, footprint);
#endif
    return n;
}
#endif

#if WF_HAS_ANISOTROPY
// KHR_materials_anisotropy at the hit: the strength (factor x texture B) and the direction in
// world space, (1, 0) or the texture's RG * 2 - 1 in the tangent frame, rotated by
// anisotropyRotation. The frame is the normal map's (TANGENT or MikkTSpace, Gram-Schmidt
// against the shading normal n); without tangent data, an arbitrary one around n.
void anisotropyAt(Instance instance, uint triangleIndex, Material material, float b1, float b2,
                  vec3 n, float footprint, out float strength, out vec3 direction) {
    strength = material.anisotropyStrength;
    vec2 d = vec2(1.0, 0.0);
#if WF_HAS_TEXTURES
    if (strength > 0.0 && material.anisotropyTexture != WF_NO_TEXTURE) {
        vec3 texel = surfaceTexture(material.anisotropyTexture, triangleIndex, b1, b2,
                                    footprint).rgb;
        d = texel.rg * 2.0 - 1.0;
        strength *= texel.b;
    }
#endif
    direction = vec3(0.0);
    if (!(strength > 0.0))
        return; // isotropic here: no tangent frame to fetch
    vec2 r = material.anisotropyRotation; // (cos, sin): counter-clockwise
    d = vec2(r.x * d.x - r.y * d.y, r.y * d.x + r.x * d.y);
    vec3 t, b;
    buildOrthonormalBasis(n, t, b);
#if WF_HAS_TANGENTS || WF_HAS_NORMAL_MAPS
    TriangleTangents frame = triangleTangentsAt(triangleIndex);
    vec3 tangent = vectorToWorld(instance, (1.0 - b1 - b2) * decodeUnit(frame.t0) +
                                               b1 * decodeUnit(frame.t1) +
                                               b2 * decodeUnit(frame.t2));
    tangent -= n * dot(n, tangent);
    float tLen = length(tangent);
    if (tLen > 1e-6) {
        t = tangent / tLen;
        bool flipped = ((frame.signs & 1u) != 0u) != instanceMirrors(instance);
        b = cross(n, t) * (flipped ? -1.0 : 1.0);
    }
#endif
    direction = t * d.x + b * d.y;
}
#endif

// Emitted radiance of a triangle's front at barycentrics (b1, b2): emissiveFactor x strength x
// emissiveTexture. Light sampling should use this too, so that NEE and BSDF hits agree.
// Level 0 also with ray cones: light sampling has no cone at the point it picks, and both must
// see one emission for MIS to weigh one integrand.
vec3 surfaceEmission(uint triangleIndex, Material material, float b1, float b2) {
    vec3 emission = material.emission;
#if WF_HAS_TEXTURES
    if (material.emissiveTexture != WF_NO_TEXTURE)
        emission *= sampleTriangleTexture(material.emissiveTexture, triangleIndex, b1, b2).rgb;
#endif
    return emission;
}

#if WF_HAS_INSTANCES
// The spawn error of a hit on an instanced triangle, in world space. The ray met the triangle
// in the mesh's space, so the intersector's slack is the mesh-space one mapped out; the world
// corners carry the rounding of their own transform; and the ray spawned here is mapped back
// into some mesh's space, which rounds once more (pbrt-v4's transformed-interaction bounds).
vec3 instancedSpawnError(Instance instance, Triangle tri, vec3 p0, vec3 p1, vec3 p2, float b1,
                         float b2, vec3 p) {
    float b0 = 1.0 - b1 - b2;
    vec3 objectCorners = b0 * abs(tri.p0) + b1 * abs(tri.p1) + b2 * abs(tri.p2);
    vec3 cornerError = affinePointError(instance.worldFromObject0, instance.worldFromObject1,
                                        instance.worldFromObject2, objectCorners);
    vec3 slack = affineErrorImage(instance.worldFromObject0, instance.worldFromObject1,
                                  instance.worldFromObject2,
                                  vec3(triangleIntersectSlack(tri.p0, tri.p1, tri.p2)));
    vec3 backError = affineErrorImage(
        instance.worldFromObject0, instance.worldFromObject1, instance.worldFromObject2,
        affinePointError(instance.objectFromWorld0, instance.objectFromWorld1,
                         instance.objectFromWorld2, abs(p)));
    return triangleHitPointError(p0, p1, p2, b1, b2) + cornerError + slack + backError;
}

// A triangle's corners in world space, through its instance.
void worldCorners(Instance instance, Triangle tri, out vec3 p0, out vec3 p1, out vec3 p2) {
    p0 = affinePoint(instance.worldFromObject0, instance.worldFromObject1,
                     instance.worldFromObject2, tri.p0);
    p1 = affinePoint(instance.worldFromObject0, instance.worldFromObject1,
                     instance.worldFromObject2, tri.p1);
    p2 = affinePoint(instance.worldFromObject0, instance.worldFromObject1,
                     instance.worldFromObject2, tri.p2);
}

// The distance along a unit-length ray from `origin` to an instanced hit, which the hit record
// does not keep (its x holds the instance): the world point as loadSurface computes it.
float instancedHitDistance(uint instanceIndex, uint triangleIndex, float b1, float b2,
                           vec3 origin) {
    vec3 p0, p1, p2;
    worldCorners(instanceAt(instanceIndex), triangleAt(triangleIndex), p0, p1, p2);
    return length(triangleHitPoint(p0, p1, p2, b1, b2) - origin);
}
#endif

// coneWidth: the ray cone's width at the hit (ray_cones.glsl; unused without WF_RAY_CONES).
SurfaceHit loadSurface(uint instanceIndex, uint triangleIndex, float b1, float b2, vec3 wo,
                       float coneWidth) {
    Triangle tri = triangleAt(triangleIndex);
    Material material = materialAt(tri.material);
    SurfaceHit s;
#if WF_HAS_INSTANCES
    Instance instance = instanceAt(instanceIndex);
    vec3 p0, p1, p2;
    worldCorners(instance, tri, p0, p1, p2);
    s.p = triangleHitPoint(p0, p1, p2, b1, b2);
    s.pError = instancedSpawnError(instance, tri, p0, p1, p2, b1, b2, s.p);
#else
    Instance instance; // unused: one-level scenes are in world space
    vec3 p0 = tri.p0;
    vec3 p1 = tri.p1;
    vec3 p2 = tri.p2;
    s.p = triangleHitPoint(p0, p1, p2, b1, b2);
    s.pError = triangleSpawnError(p0, p1, p2, b1, b2);
#endif
    vec3 cross12 = cross(p1 - p0, p2 - p0);
    s.area = 0.5 * length(cross12);
    // Mirrored, the world corners wind the other way round the face the file made the front.
    vec3 ng = normalize(cross12) * (instanceMirrors(instance) ? -1.0 : 1.0);
    s.frontFace = dot(ng, wo) > 0.0;
    s.ng = s.frontFace ? ng : -ng; // two-sided shading
#if WF_RAY_CONES
    float footprint = coneFootprint(coneWidth, dot(ng, wo), length(cross12));
#else
    float footprint = 0.0;
#endif
    vec3 ns = frontShadingNormal(instance, triangleIndex, material, b1, b2, ng, footprint);
    s.ns = s.frontFace ? ns : -ns;
    // A shading normal past the horizon of the geometric one would leak light: use ng there.
    if (!(dot(s.ns, s.ng) > 0.0))
        s.ns = s.ng;
    s.material = tri.material;
    s.emitter = tri.emitter;
    vec4 base = material.baseColor;
#if WF_HAS_VERTEX_COLORS
    base *= vertexColorAt(triangleIndex, b1, b2);
#endif
    s.metallic = material.metallic;
    s.roughness = material.roughness;
    s.ior = material.ior;
    s.transmission = material.transmission;
    s.specular = material.specular;
    s.specularColor = material.specularColor;
#if WF_HAS_TEXTURES
    if (material.baseColorTexture != WF_NO_TEXTURE)
        base *= surfaceTexture(material.baseColorTexture, triangleIndex, b1, b2, footprint);
    if (material.metallicRoughnessTexture != WF_NO_TEXTURE) {
        vec4 mr = surfaceTexture(material.metallicRoughnessTexture, triangleIndex, b1, b2,
                                 footprint);
        s.metallic *= mr.b;
        s.roughness *= mr.g;
    }
    if (material.transmissionTexture != WF_NO_TEXTURE)
        s.transmission *= surfaceTexture(material.transmissionTexture, triangleIndex, b1, b2,
                                         footprint).r;
#if WF_HAS_SPECULAR_TEXTURES
    // KHR_materials_specular: the strength in A, the colour in RGB (sRGB).
    if (material.specularTexture != WF_NO_TEXTURE)
        s.specular *= surfaceTexture(material.specularTexture, triangleIndex, b1, b2, footprint).a;
    if (material.specularColorTexture != WF_NO_TEXTURE)
        s.specularColor *= surfaceTexture(material.specularColorTexture, triangleIndex, b1, b2,
                                          footprint).rgb;
#endif
#endif
#if WF_HAS_CLEARCOAT
    s.clearcoat = material.clearcoat;
    s.clearcoatRoughness = material.clearcoatRoughness;
#if WF_HAS_TEXTURES && WF_HAS_CLEARCOAT_TEXTURES
    // KHR_materials_clearcoat: the strength in R, the roughness in G.
    if (material.clearcoatTexture != WF_NO_TEXTURE)
        s.clearcoat *= surfaceTexture(material.clearcoatTexture, triangleIndex, b1, b2,
                                      footprint).r;
    if (material.clearcoatRoughnessTexture != WF_NO_TEXTURE)
        s.clearcoatRoughness *= surfaceTexture(material.clearcoatRoughnessTexture, triangleIndex,
                                               b1, b2, footprint).g;
#endif
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    s.coatNormal = s.ns; // the base's shading normal, unless the coat has its own map
    if (material.clearcoatNormalTexture != WF_NO_TEXTURE) {
        vec3 coat = frontCoatNormal(instance, triangleIndex, material, b1, b2, ng, footprint);
        s.coatNormal = s.frontFace ? coat : -coat;
        if (!(dot(s.coatNormal, s.ng) > 0.0))
            s.coatNormal = s.ng;
    }
#endif
#endif
#if WF_HAS_SHEEN
    s.sheenColor = material.sheenColor;
    s.sheenRoughness = material.sheenRoughness;
#if WF_HAS_TEXTURES && WF_HAS_SHEEN_TEXTURES
    // KHR_materials_sheen: the colour in RGB (sRGB), the roughness in A.
    if (material.sheenColorTexture != WF_NO_TEXTURE)
        s.sheenColor *= surfaceTexture(material.sheenColorTexture, triangleIndex, b1, b2,
                                       footprint).rgb;
    if (material.sheenRoughnessTexture != WF_NO_TEXTURE)
        s.sheenRoughness *= surfaceTexture(material.sheenRoughnessTexture, triangleIndex, b1, b2,
                                           footprint).a;
#endif
#endif
#if WF_HAS_VOLUME
#if WF_HAS_TEXTURES && WF_HAS_THICKNESS_TEXTURES
    // KHR_materials_volume: the thickness in G; where it is 0 the surface is thin-walled.
    float thickness = material.thickness;
    if (thickness > 0.0 && material.thicknessTexture != WF_NO_TEXTURE)
        thickness *= surfaceTexture(material.thicknessTexture, triangleIndex, b1, b2,
                                    footprint).g;
    s.absorption = thickness > 0.0 ? material.attenuation : vec3(0.0);
#else
    s.absorption = material.thickness > 0.0 ? material.attenuation : vec3(0.0);
#endif
#endif
#if WF_HAS_IRIDESCENCE
    s.iridescence = material.iridescence;
    s.iridescenceIor = material.iridescenceIor;
    s.iridescenceThickness = material.iridescenceThicknessMaximum;
#if WF_HAS_TEXTURES
    if (material.iridescence > 0.0 && material.iridescenceTexture != WF_NO_TEXTURE)
        s.iridescence *= surfaceTexture(material.iridescenceTexture, triangleIndex, b1, b2,
                                        footprint).r;
    if (material.iridescence > 0.0 && material.iridescenceThicknessTexture != WF_NO_TEXTURE)
        s.iridescenceThickness = mix(material.iridescenceThicknessMinimum,
                                     material.iridescenceThicknessMaximum,
                                     surfaceTexture(material.iridescenceThicknessTexture,
                                                    triangleIndex, b1, b2, footprint).g);
#endif
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION
    s.diffuseTransmission = material.diffuseTransmission;
    s.diffuseTransmissionColor = material.diffuseTransmissionColor;
#if WF_HAS_TEXTURES
    // KHR_materials_diffuse_transmission: the factor in A, the colour in RGB (sRGB).
    if (material.diffuseTransmission > 0.0 &&
        material.diffuseTransmissionTexture != WF_NO_TEXTURE)
        s.diffuseTransmission *= surfaceTexture(material.diffuseTransmissionTexture,
                                                triangleIndex, b1, b2, footprint).a;
    if (material.diffuseTransmission > 0.0 &&
        material.diffuseTransmissionColorTexture != WF_NO_TEXTURE)
        s.diffuseTransmissionColor *= surfaceTexture(material.diffuseTransmissionColorTexture,
                                                     triangleIndex, b1, b2, footprint).rgb;
#endif
#endif
#if WF_HAS_DISPERSION
    s.dispersion = material.dispersion;
#endif
#if WF_HAS_ANISOTROPY
    anisotropyAt(instance, triangleIndex, material, b1, b2, ns, footprint, s.anisotropy,
                 s.anisotropyDirection);
#endif
    s.baseColor = base.rgb;
    s.alpha = base.a;
    bool emits = s.frontFace || (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u;
    s.emission = emits ? surfaceEmission(triangleIndex, material, b1, b2) : vec3(0.0);
    return s;
}
