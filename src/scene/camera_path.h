// camera_path.h - cameras that move every frame, for headless runs and the benchmark
// (--camera-path): `orbit` circles the scene at the distance of the fitted view, `dolly` flies
// from the fitted view into the middle of the assembly (a fiftieth of the bounding radius
// from its centre, reached half way) and back out, looking the same way, the distance to the
// centre changing by one factor per frame as a wheel zoom does. Plain maths, unit-tested.
#pragma once

#include <optional>
#include <string>

#include "scene/camera.h"

namespace scene {

enum class CameraPath { None, Orbit, Dolly };

const char* cameraPathName(CameraPath path);
// nullopt for a name that is no path ("none" is one).
std::optional<CameraPath> findCameraPath(const std::string& name);
std::string cameraPathNames(); // "orbit, dolly", for help and errors

// The camera of frame `frame` of `frames` along `path`, starting from `start` (the fitted
// view) around a scene with `bounds`: frame 0 is `start`, the path is closed, so frame
// `frames` would be `start` again. Near and far planes follow the eye (fitPlanes).
Camera cameraOnPath(CameraPath path, const Camera& start, const Bounds& bounds, uint32_t frame,
                    uint32_t frames);

} // namespace scene
