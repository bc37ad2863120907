// The path guide's buffers (WF_GUIDING only) and the tree walks of guide_tree.h over them.
#include "types/guide_types.h"

layout(std430, binding = WF_BINDING_GUIDE_PARAMS) readonly buffer GuideParamsBuffer {
    GuideParams guide;
};
layout(std430, binding = WF_BINDING_GUIDE_SPATIAL) readonly buffer GuideSpatialBuffer {
    GuideSpatialNode guideSpatial[];
};
layout(std430, binding = WF_BINDING_GUIDE_SAMPLING) readonly buffer GuideSamplingBuffer {
    GuideDirNode guideSampling[];
};
layout(std430, binding = WF_BINDING_GUIDE_BUILDING) readonly buffer GuideBuildingBuffer {
    GuideDirNode guideBuilding[];
};
layout(std430, binding = WF_BINDING_GUIDE_SPLATS) buffer GuideSplatBuffer {
    uint guideSplats[];
};
layout(std430, binding = WF_BINDING_GUIDE_LEAF_SAMPLES) buffer GuideLeafSampleBuffer {
    uint guideLeafSamples[];
};
layout(std430, binding = WF_BINDING_GUIDE_RECORDS) buffer GuideRecordBuffer {
    GuideRecord guideRecords[];
};
layout(std430, binding = WF_BINDING_GUIDE_COUNTS) buffer GuideCountBuffer {
    uint guideCounts[];
};

#define WF_GUIDE_SPATIAL(i) guideSpatial[i]
#define WF_GUIDE_SAMPLING(i) guideSampling[i]
#define WF_GUIDE_BUILDING(i) guideBuilding[i]
#include "guiding/guide_tree.h"
