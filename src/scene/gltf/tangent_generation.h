// MikkTSpace-compatible tangent frames (Mikkelsen 2008, the frames glTF asks for when a
// primitive has no TANGENT): per corner, dP/ds of the faces that share the corner's position,
// normal and UV and whose UV mapping has the same orientation, projected into the plane of the
// corner's normal and weighted by the face's angle there. Written from the algorithm's
// description and the reference implementation's behaviour; no code of it is used.
#pragma once
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace wf {

// Corners of a triangle soup: triangle t is corners 3t, 3t+1, 3t+2, counter-clockwise. Corners
// are joined by value (as MikkTSpace does, whatever the index buffer says), so a UV seam or a
// crease keeps its sides apart. Normals should be unit length (the loader passes the face
// normal where a primitive has none).
struct TangentCorners {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs; // (s, t) as MikkTSpace reads them: glTF's (u, -v)
};

// One tangent per corner: xyz unit and orthogonal to the corner's normal, w = +1 where the
// bitangent is cross(normal, tangent) (the UV mapping keeps its orientation), -1 where it is
// mirrored. Corners that no face with a usable UV mapping reaches (all of a face's UVs on a
// line, or a face with two equal positions and no healthy twin) get a finite frame orthogonal
// to their normal with w = +1. Non-finite input gives finite output.
std::vector<glm::vec4> generateTangents(const TangentCorners& corners);

} // namespace wf
