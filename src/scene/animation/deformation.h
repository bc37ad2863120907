// Posing a mesh's vertices on the host before the BVH is built: morph targets first (glTF:
// the base attribute plus each target's delta times its weight), then linear blend skinning
// (each vertex moved by the weighted sum of its joints' matrices, jointWorld x inverseBind).
// Arrays are flat floats, `components` per vertex, as the accessor reader gives them.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/mat4x4.hpp>

namespace wf::anim {

// values[i] += sum_t weights[t] * deltas[t][i] over the targets with a non-zero weight; every
// delta array has values.size() entries (or is null: that target lacks the attribute).
void applyMorphTargets(std::vector<float>& values, const std::vector<const float*>& deltas,
                       const std::vector<double>& weights);

// A vertex's skin matrix: sum of weights[i] x jointMatrices[joints[i]] over its `count`
// influences (JOINTS_0/1, WEIGHTS_0/1), the weights normalised to sum 1 first (exporters
// round them). All-zero weights leave the vertex where the mesh has it (the identity).
// Joint indices must be below jointMatrices.size() (the reader checks).
glm::dmat4 skinMatrix(const std::vector<glm::dmat4>& jointMatrices, const float* joints,
                      const float* weights, std::size_t count);

// Skins `count` vertices in place: positions (3 per vertex) by the skin matrix, normals (3, may
// be null) by its inverse transpose, tangents (4, w kept, may be null) by its linear part.
// `joints` and `weights` hold `influences` values per vertex (4 or 8).
void skinVertices(const std::vector<glm::dmat4>& jointMatrices, const float* joints,
                  const float* weights, std::size_t influences, std::size_t count,
                  float* positions, float* normals, float* tangents);

} // namespace wf::anim
