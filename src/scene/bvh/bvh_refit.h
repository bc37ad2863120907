// Refitting a one-level tree to moved triangles: the same topology (pair entries, leaves and
// the triangles' order) with every box recomputed bottom-up. A frame of an animation whose
// triangles keep their count and materials reuses the previous frame's tree this way at a
// fraction of a build's cost (docs/animation.md has the figures); how far the tree's quality
// drifted is read from its surface-area cost against the cost when it was built.
#pragma once
#include <vector>

#include "scene/scene.h"

namespace wf {

// Recomputes the boxes of every entry of `pairs` (one tree rooted at entry 0, as pairBvhNodes
// makes it) from `triangles`, which must be in the tree's order. InternalError on a child
// reference outside `pairs` or `triangles`.
void refitBvhPairs(std::vector<BvhPair>& pairs, const std::vector<Triangle>& triangles);

// The tree's surface-area cost with unit traversal and intersection costs: over every pair
// entry, each child box's area times its triangle count (a leaf) or 1 (an entry), divided by
// the root box's area. Comparable between one tree's refits, not between builders.
double pairTreeCost(const std::vector<BvhPair>& pairs);

} // namespace wf
