// The windowed demo's "Transparency" section of the ImGui panel: the opacity of each object the forward
// pass draws (the objects that were drawn forward since the scene was loaded stay listed at opacity 1),
// and per particle emitter: on/off, count, opacity, rise speed. Every value stays within the scene
// file's ranges (docs/scene-format.md#particles).
#pragma once

#include "scene/scene.h"

#include <set>

namespace demo::window {

class TransparencyControls {
public:
    // Adds the section to the current ImGui window (call between Begin and End), editing scene.objects'
    // opacity and scene.particles. Returns true if anything changed this frame.
    bool build(Scene& scene);

private:
    std::set<size_t> listed_;  // the objects shown: drawn forward at some build
};

}  // namespace demo::window
