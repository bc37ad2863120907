// The scene in the driver's acceleration structures (--traversal rt), built once per scene
// beside its tables: a bottom level per mesh tree of the scene's BVH (the whole world geometry
// in one-level scenes), with the triangles in the table's own order, so a hit's primitive
// index plus its instance's first triangle is the table's triangle index; a bottom level of
// boxes around the sphere lights, met by the project's sphere test (shaders/rt/sphere.rint);
// and a top level over the placements, in the order of the scene's instance table (so the
// instance index of a hit is the one the BVH's two-level traversal reports), then the spheres.
// Meshes with alpha-tested materials are non-opaque, for the any-hit alpha test.
#pragma once
#include <memory>

#include "gpu/acceleration_structure.h"

namespace wf {

class Context;
struct PreparedScene;
struct ShaderVariant;

// Hit groups of the ray-tracing passes (shader binding table offsets).
constexpr uint32_t kTriangleHitGroup = 0;
constexpr uint32_t kSphereHitGroup = 1;

std::unique_ptr<AccelerationStructureSet> buildSceneAcceleration(const Context& context,
                                                                 const PreparedScene& scene,
                                                                 const ShaderVariant& variant);

} // namespace wf
