#pragma once
// The camera is GL-free math and lives in view/; render/surface_renderer.h still names this path.
#include "view/camera.h"
