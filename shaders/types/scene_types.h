// Scene data as the GPU reads it (std430). Included by C++ and GLSL; the C++ side asserts the
// layout, so no struct is ever mirrored by hand.
#ifndef WF_SCENE_TYPES_H
#define WF_SCENE_TYPES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_NO_EMITTER 0xffffffffu

// A triangle in world space. vec3 + uint pack into 16 bytes in std430 and in C++ alike.
struct Triangle {
    vec3 p0;
    uint material;
    vec3 p1;
    uint emitter; // index into the emitter table, or WF_NO_EMITTER
    vec3 p2;
    uint pad;
};

// Flattened BVH node in depth-first order: an interior node's left child is the next node,
// its right child is `rightOrFirst`; a leaf holds `count` > 0 triangles from `rightOrFirst`.
struct BvhNode {
    vec3 lo;
    uint rightOrFirst;
    vec3 hi;
    uint count;
};

// What traversal walks (GPU and CPU alike), made from the BvhNode tree by pairBvhNodes
// (bvh_builder.h): one entry per interior node holding both children's boxes, so visiting a
// node is one 64-byte fetch and reaching a leaf costs no fetch at all. A child reference packs
// index << WF_BVH_COUNT_BITS | count: count 0 is the pair entry `index`, count > 0 a leaf of
// `count` triangles from triangle `index`; WF_BVH_NO_CHILD is no child. One word per child
// keeps the traversal stack to one word per entry. Entry 0 holds the root's children (or the
// root itself when it is a leaf; no children for an empty scene).
struct BvhPair {
    vec3 lo0;
    uint child0;
    vec3 hi0;
    uint pad0;
    vec3 lo1;
    uint child1;
    vec3 hi1;
    uint pad1;
};

// One placement of a mesh in a two-level scene (WF_HAS_INSTANCES): the top-level BVH's leaves
// index these, in leaf order. Rows of the 3x4 affine maps: x' = dot(row0.xyz, x) + row0.w.
// The scene's singly placed geometry is one more instance, with the identity.
struct Instance {
    vec4 objectFromWorld0;
    vec4 objectFromWorld1;
    vec4 objectFromWorld2;
    vec4 worldFromObject0;
    vec4 worldFromObject1;
    vec4 worldFromObject2;
    uint blasRoot; // the pair entry that holds its mesh BVH's root children
    uint flags;    // WF_INSTANCE_*
    // WF_INSTANCE_MOVING: its first key in the motion-key table (motion.glsl), 3 rows of
    // worldFromObject per key; the maps above are then the shutter's centre.
    uint motionKeys;
    uint pad1;
};

// The transform mirrors space (negative determinant): front faces and tangent frames flip.
#define WF_INSTANCE_MIRRORED 1u
// The placement moves within the shutter (WF_MOTION): a ray sees it at the ray's time.
#define WF_INSTANCE_MOVING 2u

#define WF_BVH_COUNT_BITS 5u
#define WF_BVH_MAX_LEAF_COUNT 31u // (1 << WF_BVH_COUNT_BITS) - 1
// Stack entries that BvhRegisterStack (bvh_traverse.h) holds: 8, or 16 for any-hit rays.
#define WF_BVH_REGISTER_STACK_SIZE 16u
#define WF_BVH_NO_CHILD 0xffffffffu

#define WF_MATERIAL_DOUBLE_SIDED 1u
#define WF_MATERIAL_ALPHA_MASK 2u  // alpha below alphaCutoff is a hole, for every ray
#define WF_MATERIAL_ALPHA_BLEND 4u // see the loader for how BLEND is approximated
// Bits 3-4, set only in the table the GPU reads: the shade bin of the material's kind
// (WF_SHADE_BINS; src/passes/shade_kinds.h).
#define WF_MATERIAL_SHADE_BIN_SHIFT 3u
#define WF_MATERIAL_SHADE_BIN_MASK 3u
#define WF_NO_TEXTURE 0xffffffffu

// glTF metallic-roughness material with KHR_materials_specular, _transmission, _ior,
// _emissive_strength, _clearcoat, _sheen, _volume and _iridescence folded in. Texture fields index the
// texture-reference table, or hold WF_NO_TEXTURE.
struct Material {
    vec4 baseColor;     // rgb: linear base colour, a: alpha
    vec3 emission;      // emissiveFactor x KHR_materials_emissive_strength
    uint flags;         // WF_MATERIAL_*
    float metallic;
    float roughness;    // perceptual roughness; alpha = roughness^2
    float ior;          // KHR_materials_ior, 1.5 by default
    float transmission; // KHR_materials_transmission factor
    vec3 specularColor; // KHR_materials_specular specularColorFactor
    float specular;     // KHR_materials_specular specularFactor; 0 leaves exact Lambert
    float alphaCutoff;
    float normalScale;
    uint baseColorTexture;
    uint metallicRoughnessTexture;
    uint normalTexture;
    uint emissiveTexture;
    uint transmissionTexture;
    uint specularTexture;      // its A channel multiplies specular
    uint specularColorTexture; // its RGB (sRGB) multiplies specularColor
    float clearcoat;           // KHR_materials_clearcoat clearcoatFactor; 0: no coat
    float clearcoatRoughness;
    uint pad;
    vec3 sheenColor;           // KHR_materials_sheen sheenColorFactor; 0: no sheen
    float sheenRoughness;
    vec3 attenuation;          // KHR_materials_volume sigma_a = -ln(attenuationColor) / distance
    float thickness;           // thicknessFactor; 0 is thin-walled: no attenuation
    float iridescence;         // KHR_materials_iridescence iridescenceFactor; 0: no film
    float iridescenceIor;      // the film's ior, 1.3 by default
    float iridescenceThicknessMinimum; // nm, 100 by default: thickness texture G = 0
    float iridescenceThicknessMaximum; // nm, 400 by default: thickness texture G = 1 (and
                                       // the film's thickness without a texture)
    uint iridescenceTexture;           // its R channel multiplies iridescence
    uint iridescenceThicknessTexture;  // its G channel mixes minimum..maximum
    uint pad1;
    uint pad2;
    // --- The layers' and volume's textures (issue 48), texels 11-12: read by the shaders only
    // where the scene uses them (WF_HAS_CLEARCOAT_TEXTURES, _CLEARCOAT_NORMAL_MAPS,
    // _SHEEN_TEXTURES, _THICKNESS_TEXTURES). Each with its own KHR_texture_transform.
    uint clearcoatTexture;          // its R channel multiplies clearcoat
    uint clearcoatRoughnessTexture; // its G channel multiplies clearcoatRoughness
    uint clearcoatNormalTexture;    // the coat's own tangent-space normal map
    float clearcoatNormalScale;     // clearcoatNormalTexture.scale, 1 by default
    uint sheenColorTexture;         // its RGB (sRGB) multiplies sheenColor
    uint sheenRoughnessTexture;     // its A channel multiplies sheenRoughness
    uint thicknessTexture;          // its G channel multiplies thickness
    uint pad3;
    // KHR_materials_anisotropy (texel 13; read by shaders only where WF_HAS_ANISOTROPY). Kept
    // in a block of its own at the end.
    float anisotropyStrength; // anisotropyStrength; 0: isotropic
    uint anisotropyTexture;   // RG: direction in the tangent frame ([-1, 1]); B x strength
    vec2 anisotropyRotation;  // (cos, sin) of anisotropyRotation: counter-clockwise from the
                              // tangent towards the bitangent
    // KHR_materials_diffuse_transmission (texels 14-15; read by shaders only where
    // WF_HAS_DIFFUSE_TRANSMISSION): the share of the diffuse base that crosses the surface.
    vec3 diffuseTransmissionColor;        // diffuseTransmissionColorFactor, white by default
    float diffuseTransmission;            // diffuseTransmissionFactor; 0: none
    uint diffuseTransmissionTexture;      // its A channel multiplies diffuseTransmission
    uint diffuseTransmissionColorTexture; // its RGB (sRGB) multiplies diffuseTransmissionColor
    // KHR_materials_dispersion (texel 15's z; read by shaders only where WF_HAS_DISPERSION):
    // 20 / Abbe number; 0: no dispersion (the ior is n_d at every wavelength).
    float dispersion;
    uint pad5;
};

// Per-scene switches for the material extensions (ShaderVariant), off in shaders compiled
// without them. (C++ tests of bsdf_layers.h compile both layers.)
#ifndef __cplusplus
#ifndef WF_HAS_CLEARCOAT
#define WF_HAS_CLEARCOAT 0
#endif
#ifndef WF_HAS_SHEEN
#define WF_HAS_SHEEN 0
#endif
#ifndef WF_HAS_VOLUME
#define WF_HAS_VOLUME 0
#endif
#ifndef WF_HAS_SPECULAR_TEXTURES
#define WF_HAS_SPECULAR_TEXTURES 0
#endif
#ifndef WF_HAS_IRIDESCENCE
#define WF_HAS_IRIDESCENCE 0
#endif
#ifndef WF_HAS_CLEARCOAT_TEXTURES
#define WF_HAS_CLEARCOAT_TEXTURES 0
#endif
#ifndef WF_HAS_CLEARCOAT_NORMAL_MAPS
#define WF_HAS_CLEARCOAT_NORMAL_MAPS 0
#endif
#ifndef WF_HAS_SHEEN_TEXTURES
#define WF_HAS_SHEEN_TEXTURES 0
#endif
#ifndef WF_HAS_THICKNESS_TEXTURES
#define WF_HAS_THICKNESS_TEXTURES 0
#endif
#ifndef WF_HAS_ANISOTROPY
#define WF_HAS_ANISOTROPY 0
#endif
#ifndef WF_HAS_DIFFUSE_TRANSMISSION
#define WF_HAS_DIFFUSE_TRANSMISSION 0
#endif
#ifndef WF_HAS_DISPERSION
#define WF_HAS_DISPERSION 0
#endif
#endif

// The kind of light an emitter-table entry refers to, in the top two bits of `source`.
#define WF_EMITTER_TRIANGLE 0x00000000u    // | triangle index
#define WF_EMITTER_LIGHT 0x40000000u       // | index into the punctual/sphere light table
#define WF_EMITTER_ENVIRONMENT 0x80000000u
#define WF_EMITTER_TREE 0xc0000000u // the light tree's slot in the table: walk the tree
#define WF_EMITTER_KIND_MASK 0xc0000000u
#define WF_EMITTER_INDEX_MASK 0x3fffffffu

// One light in the light table, chosen by power through a Walker alias table.
struct Emitter {
    uint source;     // WF_EMITTER_* | index
    float pmf;       // probability of choosing this emitter
    float aliasProb; // alias-table threshold for this slot
    uint alias;      // slot taken when the threshold test fails
};

// The tables above are read in shaders as RGBA32UI texels (scene_tables.glsl), so each struct
// is a whole number of 16-byte texels.
#define WF_TRIANGLE_TEXELS 3u
#define WF_BVH_PAIR_TEXELS 4u
// Pages (buffers) the triangle, BVH and instance tables may span, of 2^shift entries each: set
// per scene by the host (ShaderVariant), defaults for code compiled without them.
#define WF_MAX_TABLE_PAGES 8u
#ifndef WF_TRIANGLE_PAGES
#define WF_TRIANGLE_PAGES 1
#define WF_TRIANGLE_PAGE_SHIFT 31
#endif
#ifndef WF_BVH_PAGES
#define WF_BVH_PAGES 1
#define WF_BVH_PAGE_SHIFT 31
#endif
#ifndef WF_INSTANCE_PAGES
#define WF_INSTANCE_PAGES 1
#define WF_INSTANCE_PAGE_SHIFT 31
#endif
#define WF_MATERIAL_TEXELS 16u
#define WF_INSTANCE_TEXELS 7u

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::Triangle) == 16 * WF_TRIANGLE_TEXELS);
static_assert(sizeof(wf::gpu_types::BvhPair) == 16 * WF_BVH_PAIR_TEXELS);
static_assert(offsetof(wf::gpu_types::BvhPair, child0) == 12);
static_assert(offsetof(wf::gpu_types::BvhPair, child1) == 44);
static_assert(sizeof(wf::gpu_types::Material) == 16 * WF_MATERIAL_TEXELS);
static_assert(sizeof(wf::gpu_types::Triangle) == 48);
namespace wf::gpu_types {
// KHR_materials_dispersion acts where light refracts: on transmissive materials only
// (WF_HAS_DISPERSION, the integrators' refusal, --verbose's count).
inline bool materialDisperses(const Material& m) {
    return m.dispersion > 0.0f && m.transmission > 0.0f;
}
} // namespace wf::gpu_types
static_assert(offsetof(wf::gpu_types::Triangle, p1) == 16);
static_assert(offsetof(wf::gpu_types::Triangle, emitter) == 28);
static_assert(offsetof(wf::gpu_types::Triangle, p2) == 32);
static_assert(sizeof(wf::gpu_types::BvhNode) == 32);
static_assert(offsetof(wf::gpu_types::BvhNode, hi) == 16);
static_assert(offsetof(wf::gpu_types::BvhNode, count) == 28);
static_assert(sizeof(wf::gpu_types::Material) == 256);
static_assert(offsetof(wf::gpu_types::Material, emission) == 16);
static_assert(offsetof(wf::gpu_types::Material, flags) == 28);
static_assert(offsetof(wf::gpu_types::Material, specularColor) == 48);
static_assert(offsetof(wf::gpu_types::Material, specular) == 60);
static_assert(offsetof(wf::gpu_types::Material, specularTexture) == 92);
static_assert(offsetof(wf::gpu_types::Material, specularColorTexture) == 96);
static_assert(offsetof(wf::gpu_types::Material, pad) == 108);
static_assert(offsetof(wf::gpu_types::Material, sheenColor) == 112);
static_assert(offsetof(wf::gpu_types::Material, sheenRoughness) == 124);
static_assert(offsetof(wf::gpu_types::Material, attenuation) == 128);
static_assert(offsetof(wf::gpu_types::Material, thickness) == 140);
static_assert(offsetof(wf::gpu_types::Material, iridescence) == 144);
static_assert(offsetof(wf::gpu_types::Material, iridescenceThicknessMaximum) == 156);
static_assert(offsetof(wf::gpu_types::Material, iridescenceTexture) == 160);
static_assert(offsetof(wf::gpu_types::Material, iridescenceThicknessTexture) == 164);
static_assert(offsetof(wf::gpu_types::Material, pad2) == 172);
static_assert(offsetof(wf::gpu_types::Material, clearcoatTexture) == 176);
static_assert(offsetof(wf::gpu_types::Material, clearcoatNormalScale) == 188);
static_assert(offsetof(wf::gpu_types::Material, sheenColorTexture) == 192);
static_assert(offsetof(wf::gpu_types::Material, thicknessTexture) == 200);
static_assert(offsetof(wf::gpu_types::Material, pad3) == 204);
static_assert(offsetof(wf::gpu_types::Material, anisotropyStrength) == 208);
static_assert(offsetof(wf::gpu_types::Material, anisotropyTexture) == 212);
static_assert(offsetof(wf::gpu_types::Material, anisotropyRotation) == 216);
static_assert(offsetof(wf::gpu_types::Material, diffuseTransmissionColor) == 224);
static_assert(offsetof(wf::gpu_types::Material, diffuseTransmission) == 236);
static_assert(offsetof(wf::gpu_types::Material, diffuseTransmissionTexture) == 240);
static_assert(offsetof(wf::gpu_types::Material, dispersion) == 248);
static_assert(offsetof(wf::gpu_types::Material, pad5) == 252);
static_assert(sizeof(wf::gpu_types::Emitter) == 16);
static_assert(sizeof(wf::gpu_types::Instance) == 16 * WF_INSTANCE_TEXELS);
static_assert(offsetof(wf::gpu_types::Instance, worldFromObject0) == 48);
static_assert(offsetof(wf::gpu_types::Instance, blasRoot) == 96);
#endif

#endif
