// Lets one header compile both as GLSL and as C++: the C++ side maps GLSL's vector types and
// built-ins onto glm, so pure math (warps, intersection, RNG, ray offsets) is written once and
// tested on the CPU exactly as the GPU runs it.
#ifndef WF_GLSL_CPP_H
#define WF_GLSL_CPP_H

#ifdef __cplusplus
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

namespace wf::gpu_types {
using glm::ivec2;
using glm::ivec3;
using glm::ivec4;
using glm::mat3;
using glm::mat4;
using glm::uvec2;
using glm::uvec3;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = std::uint32_t;
} // namespace wf::gpu_types

// Parameter qualifiers: GLSL `inout T x` is C++ `T& x`.
#define WF_INOUT(T) T&
#define WF_OUT(T) T&
#define WF_CONST const
#define WF_INLINE inline
#else
#define WF_INOUT(T) inout T
#define WF_OUT(T) out T
#define WF_CONST const
#define WF_INLINE
#endif

#endif
