// A camera for scenes whose file has none: looking down -Z at the centre of the bounds, far
// enough back that the bounding sphere fits the vertical field of view.
#pragma once
#include "scene/scene.h"

namespace wf {

Camera frameBounds(const Scene& scene);

} // namespace wf
