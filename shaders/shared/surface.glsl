// What shading needs to know about a hit point, gathered in one place: position with its
// error bound for spawning rays, geometric and shading normals, and the material's values at
// that point. Texture lookups and interpolated normals (when a scene has them) live here, so
// shade.comp stays about light transport. Per-scene switches (texture_types.h): WF_HAS_NORMALS
// interpolates vertex normals, WF_HAS_NORMAL_MAPS perturbs them with the normal texture,
// WF_HAS_TEXTURES multiplies the factors by their textures (glTF metallic-roughness: B is
// metalness, G roughness; colour textures are sRGB-decoded in textures.glsl), and
// WF_HAS_SPECULAR_TEXTURES the KHR_materials_specular maps. WF_HAS_CLEARCOAT, WF_HAS_SHEEN and
// WF_HAS_VOLUME carry those extensions' factors (their textures are not supported).
#include "textures.glsl"

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
#endif
#if WF_HAS_SHEEN
    vec3 sheenColor;
    float sheenRoughness;
#endif
#if WF_HAS_VOLUME
    vec3 absorption; // sigma_a behind the surface (KHR_materials_volume); zero if thin-walled
#endif
};

vec3 decodeUnit(uint packed) { return octDecode(unpackSnorm2x16(packed)); }

// The shading normal on the front (counter-clockwise) side: interpolated vertex normals, then
// the normal map in the tangent frame. Falls back to the geometric normal wherever the data
// would give a zero or non-finite vector.
vec3 frontShadingNormal(uint triangleIndex, Material material, float b1, float b2, vec3 ng) {
    vec3 n = ng;
#if WF_HAS_NORMALS
    TriangleNormals corners = triangleNormalsAt(triangleIndex);
    float b0 = 1.0 - b1 - b2;
    vec3 sum = b0 * decodeUnit(corners.n0) + b1 * decodeUnit(corners.n1) +
               b2 * decodeUnit(corners.n2);
    float len = length(sum);
    n = len > 1e-6 ? sum / len : ng;
#endif
#if WF_HAS_NORMAL_MAPS
    if (material.normalTexture != WF_NO_TEXTURE) {
        TriangleTangents frame = triangleTangentsAt(triangleIndex);
        vec3 t = (1.0 - b1 - b2) * decodeUnit(frame.t0) + b1 * decodeUnit(frame.t1) +
                 b2 * decodeUnit(frame.t2);
        t -= n * dot(n, t); // Gram-Schmidt against the interpolated normal
        float tLen = length(t);
        if (tLen > 1e-6) {
            t /= tLen;
            vec3 b = cross(n, t) * ((frame.signs & 1u) != 0u ? -1.0 : 1.0);
            vec3 m = sampleTriangleTexture(material.normalTexture, triangleIndex, b1, b2).xyz;
            m = m * 2.0 - 1.0;
            m.xy *= material.normalScale;
            vec3 mapped = t * m.x + b * m.y + n * m.z;
            float mLen = length(mapped);
            n = mLen > 1e-6 ? mapped / mLen : n;
        }
    }
#endif
    return n;
}

// Emitted radiance of a triangle's front at barycentrics (b1, b2): emissiveFactor x strength x
// emissiveTexture. Light sampling should use this too, so that NEE and BSDF hits agree.
vec3 surfaceEmission(uint triangleIndex, Material material, float b1, float b2) {
    vec3 emission = material.emission;
#if WF_HAS_TEXTURES
    if (material.emissiveTexture != WF_NO_TEXTURE)
        emission *= sampleTriangleTexture(material.emissiveTexture, triangleIndex, b1, b2).rgb;
#endif
    return emission;
}

SurfaceHit loadSurface(uint triangleIndex, float b1, float b2, vec3 wo) {
    Triangle tri = triangleAt(triangleIndex);
    Material material = materialAt(tri.material);
    SurfaceHit s;
    s.p = triangleHitPoint(tri.p0, tri.p1, tri.p2, b1, b2);
    s.pError = triangleSpawnError(tri.p0, tri.p1, tri.p2, b1, b2);
    vec3 cross12 = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    s.area = 0.5 * length(cross12);
    vec3 ng = normalize(cross12);
    s.frontFace = dot(ng, wo) > 0.0;
    s.ng = s.frontFace ? ng : -ng; // two-sided shading
    vec3 ns = frontShadingNormal(triangleIndex, material, b1, b2, ng);
    s.ns = s.frontFace ? ns : -ns;
    // A shading normal past the horizon of the geometric one would leak light: use ng there.
    if (!(dot(s.ns, s.ng) > 0.0))
        s.ns = s.ng;
    s.material = tri.material;
    s.emitter = tri.emitter;
    vec4 base = material.baseColor;
    s.metallic = material.metallic;
    s.roughness = material.roughness;
    s.ior = material.ior;
    s.transmission = material.transmission;
    s.specular = material.specular;
    s.specularColor = material.specularColor;
#if WF_HAS_TEXTURES
    if (material.baseColorTexture != WF_NO_TEXTURE)
        base *= sampleTriangleTexture(material.baseColorTexture, triangleIndex, b1, b2);
    if (material.metallicRoughnessTexture != WF_NO_TEXTURE) {
        vec4 mr = sampleTriangleTexture(material.metallicRoughnessTexture, triangleIndex, b1, b2);
        s.metallic *= mr.b;
        s.roughness *= mr.g;
    }
    if (material.transmissionTexture != WF_NO_TEXTURE)
        s.transmission *= sampleTriangleTexture(material.transmissionTexture, triangleIndex, b1,
                                                b2).r;
#if WF_HAS_SPECULAR_TEXTURES
    // KHR_materials_specular: the strength in A, the colour in RGB (sRGB).
    if (material.specularTexture != WF_NO_TEXTURE)
        s.specular *= sampleTriangleTexture(material.specularTexture, triangleIndex, b1, b2).a;
    if (material.specularColorTexture != WF_NO_TEXTURE)
        s.specularColor *=
            sampleTriangleTexture(material.specularColorTexture, triangleIndex, b1, b2).rgb;
#endif
#endif
#if WF_HAS_CLEARCOAT
    s.clearcoat = material.clearcoat;
    s.clearcoatRoughness = material.clearcoatRoughness;
#endif
#if WF_HAS_SHEEN
    s.sheenColor = material.sheenColor;
    s.sheenRoughness = material.sheenRoughness;
#endif
#if WF_HAS_VOLUME
    s.absorption = material.thickness > 0.0 ? material.attenuation : vec3(0.0);
#endif
    s.baseColor = base.rgb;
    s.alpha = base.a;
    bool emits = s.frontFace || (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u;
    s.emission = emits ? surfaceEmission(triangleIndex, material, b1, b2) : vec3(0.0);
    return s;
}
