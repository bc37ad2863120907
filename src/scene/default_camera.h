// Choosing the camera to render with: one of the file's (--camera NAME|INDEX) or, for scenes
// whose file has none, one looking down -Z at the centre of the bounds, far enough back that
// the bounding sphere fits the vertical field of view.
#pragma once
#include <string>

#include "scene/scene.h"

namespace wf {

Camera frameBounds(const Scene& scene);

// The file's camera named `nameOrIndex` (names first, then a decimal index into
// scene.cameras). Throws InputError("<file>: ...") listing the cameras there are otherwise.
Camera selectCamera(const Scene& scene, const std::string& nameOrIndex, const std::string& file);

} // namespace wf
