// The render's camera (params) as camera_importance.h's CameraGeometry: what light subpaths
// connect to and BDPT's camera subpaths start from; with WF_MOTION, a moving camera where it
// is at the path's time, as camera_ray.glsl places it. Needs bindings.glsl (params).
#ifndef WF_SCENE_CAMERA_GLSL
#define WF_SCENE_CAMERA_GLSL
#include "bidir/camera_importance.h"

CameraGeometry sceneCamera() {
    CameraGeometry camera;
    camera.position = params.cameraPosition;
    camera.tanHalfFovY = params.tanHalfFovY;
    camera.forward = params.cameraForward;
    camera.aspect = params.aspect;
    camera.right = params.cameraRight;
#if WF_THIN_LENS
    camera.lensRadius = params.lensRadius;
    camera.focusDistance = params.focusDistance;
#else
    camera.lensRadius = 0.0;
    camera.focusDistance = 1.0;
#endif
    camera.up = params.cameraUp;
#if WF_MOTION
    if (params.cameraMotionKeys != 0u)
        movingCameraFrame(camera.position, camera.forward, camera.right, camera.up);
#endif
    camera.width = params.width;
    camera.height = params.height;
    camera.orthoHalfHeight = params.orthoHalfHeight;
    return camera;
}

#endif
