// Closed forms of the irradiance that each kind of light gives a point with unit normal n
// (light from the side n points to only), for the light-agreement tests. None of them shares
// code with the renderer's sampling: they integrate the light exactly instead.
#pragma once
#include <glm/glm.hpp>

namespace wf::test {

// A uniform sphere of radiance L seen from p, clipped by p's horizon (Snyder 1996: the
// cosine-weighted solid angle of a spherical cap cut by a plane). 0 from inside the sphere,
// where only the inside, which does not emit, can be seen.
double sphereIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 center, double radius,
                        double radiance);

constexpr int kMaxPolygonVertices = 8;

// A planar convex polygon (at most kMaxPolygonVertices) of radiance L emitting from its front face (counter-clockwise
// vertices seen from the front), clipped by p's horizon: Lambert's formula, half the sum over
// the edges of the angle they subtend times the normal's share of their plane.
double polygonIrradiance(glm::dvec3 p, glm::dvec3 n, const glm::dvec3* vertices, int count,
                         double radiance);

// A point light of intensity I (W/sr), and glTF's spot with its smooth falloff between the
// outer and inner cone (x^2 of the linear ramp in cos angle), aimed along `direction`.
double pointIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 position, double intensity);
double spotIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 position, glm::dvec3 direction,
                      double cosInner, double cosOuter, double intensity);

// A directional light travelling along `direction` with illuminance E at normal incidence.
double directionalIrradiance(glm::dvec3 n, glm::dvec3 direction, double illuminance);

} // namespace wf::test
