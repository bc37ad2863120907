// Motion blur (WF_MOTION): what moves within the shutter is seen by each ray at the ray's time.
// Every moving thing has params.motionSegments + 1 keys evenly spaced over the shutter, read
// linearly interpolated: an instance's worldFromObject rows (3 vec4 per key), a light's position
// (1 vec4), the camera's frame (3 vec4: position, forward, up). Interpolating the affine
// map itself keeps every point of a moving mesh on the segment between its keyed positions, so
// the union of the keys' boxes bounds the motion (the top level's boxes are built so).
//
// wfRayTime is the time of the path the invocation works on, in [0, 1) over the shutter: the
// raygen pass draws it (WF_DIM_TIME) and stores it per path; the other passes set it from there
// before they trace or shade. Without WF_MOTION the records are read as stored.
// Needs bindings.glsl (included at its end).
#ifndef WF_MOTION_GLSL
#define WF_MOTION_GLSL

#ifndef WF_MOTION
#define WF_MOTION 0
#endif

#if WF_MOTION
layout(std430, binding = WF_BINDING_MOTION_KEYS) readonly buffer MotionKeyBuffer {
    vec4 motionKeys[];
};
layout(std430, binding = WF_BINDING_RAY_TIME) buffer RayTimeBuffer {
    float rayTime[];
};

float wfRayTime = 0.0;

// The time of the path being worked on, for records that carry it to a later pass.
float pathTime() { return wfRayTime; }

// The key segment holding `time` and the fraction along it.
uint motionSegment(float time, out float along) {
    float x = clamp(time, 0.0, 1.0) * float(params.motionSegments);
    uint segment = min(uint(x), params.motionSegments - 1u);
    along = x - float(segment);
    return segment;
}

// Key `first` + segment x stride, interpolated: the value of a moving thing at the ray's time.
vec4 motionKeyAt(uint first, uint stride, uint row) {
    float along;
    uint key = first + motionSegment(wfRayTime, along) * stride + row;
    return mix(motionKeys[key], motionKeys[key + stride], along);
}

// A moving camera's frame at the path's time (params.cameraMotionKeys != 0): its keys
// interpolated, made orthonormal again as the host makes it (cameraRight).
void movingCameraFrame(out vec3 position, out vec3 forward, out vec3 right, out vec3 up) {
    uint first = params.cameraMotionKeys - 1u;
    position = motionKeyAt(first, 3u, 0u).xyz;
    forward = normalize(motionKeyAt(first, 3u, 1u).xyz);
    right = normalize(cross(forward, motionKeyAt(first, 3u, 2u).xyz));
    up = cross(right, forward);
}
#else
float pathTime() { return 0.0; } // nothing moves: every path is at the shutter's one instant
#endif

#if WF_HAS_INSTANCES
Instance instanceAt(uint index) {
    Instance instance = instanceRecordAt(index);
#if WF_MOTION
    if ((instance.flags & WF_INSTANCE_MOVING) != 0u) {
        vec4 r0 = motionKeyAt(instance.motionKeys, 3u, 0u);
        vec4 r1 = motionKeyAt(instance.motionKeys, 3u, 1u);
        vec4 r2 = motionKeyAt(instance.motionKeys, 3u, 2u);
        instance.worldFromObject0 = r0;
        instance.worldFromObject1 = r1;
        instance.worldFromObject2 = r2;
        // mat3 takes columns, so this is the linear part transposed and its inverse's columns
        // are the inverse's rows. Rigid and scaled placements are well conditioned; the float
        // inverse then errs by a few ulps, as the stored (double-made) one does after rounding.
        mat3 inverseT = inverse(mat3(r0.xyz, r1.xyz, r2.xyz));
        vec3 t = vec3(r0.w, r1.w, r2.w);
        instance.objectFromWorld0 = vec4(inverseT[0], -dot(inverseT[0], t));
        instance.objectFromWorld1 = vec4(inverseT[1], -dot(inverseT[1], t));
        instance.objectFromWorld2 = vec4(inverseT[2], -dot(inverseT[2], t));
    }
#endif
    return instance;
}
#endif

#if WF_HAS_LIGHTS
PunctualLight lightAt(uint index) {
    PunctualLight light = lightRecordAt(index);
#if WF_MOTION
    if (light.motion != 0u)
        light.position = motionKeyAt(light.motion - 1u, 1u, 0u).xyz;
#endif
    return light;
}
#endif

#endif
