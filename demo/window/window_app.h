// The windowed demo: a GLFW window with a Vulkan swapchain, showing the demo renderer's frames (HDR after
// postfx, tonemapped on the GPU) with a Dear ImGui overlay and a free-flight camera.
#pragma once

#include "scene/scene.h"

#include <cstdint>

namespace demo::window {

struct AppOptions {
    uint32_t width = 1280;  // initial window size [screen coordinates]
    uint32_t height = 720;
    uint32_t frames = 0;  // exit after this many presented frames; 0: until the window is closed / Esc
    bool ui = true;       // the ImGui overlay
    bool validation = false;
    bool hold = false;  // after `frames` frames, keep the window showing the last one until stdin ends
};

// Runs the window; glfwInit must have succeeded (the caller terminates GLFW). Errors are printed as one
// line "postfx-demo: <message>". Returns the process exit code: 0, or 1 on any error, including
// validation messages when validation is on.
int runWindow(const AppOptions& options, const Scene& scene);

}  // namespace demo::window
