// What shading needs to know about a hit point, gathered in one place: position with its
// error bound for spawning rays, geometric and shading normals, and the material's values at
// that point. Texture lookups and interpolated normals (when a scene has them) belong here,
// so shade.comp stays about light transport.

struct SurfaceHit {
    vec3 p;          // hit point from barycentrics
    vec3 pError;     // conservative bound for offsetRayOrigin
    vec3 ng;         // unit geometric normal, facing the side the ray arrived from
    vec3 ns;         // unit shading normal, same side as ng
    bool frontFace;  // the ray hit the counter-clockwise side
    float area;      // triangle area, for the emitter pdf
    uint material;
    uint emitter;    // WF_NO_EMITTER unless the triangle is in the light table
    vec3 baseColor;
    float metallic;
    float roughness;
    vec3 emission;   // already zero for faces that do not emit
};

SurfaceHit loadSurface(uint triangleIndex, float b1, float b2, vec3 wo) {
    Triangle tri = triangles[triangleIndex];
    Material material = materials[tri.material];
    SurfaceHit s;
    s.p = triangleHitPoint(tri.p0, tri.p1, tri.p2, b1, b2);
    s.pError = triangleSpawnError(tri.p0, tri.p1, tri.p2, b1, b2);
    vec3 cross12 = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    s.area = 0.5 * length(cross12);
    vec3 ng = normalize(cross12);
    s.frontFace = dot(ng, wo) > 0.0;
    s.ng = s.frontFace ? ng : -ng; // two-sided shading
    s.ns = s.ng;
    s.material = tri.material;
    s.emitter = tri.emitter;
    s.baseColor = material.baseColor.rgb;
    s.metallic = material.metallic;
    s.roughness = material.roughness;
    bool emits = s.frontFace || (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u;
    s.emission = emits ? material.emission : vec3(0.0);
    return s;
}
