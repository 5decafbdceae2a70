// The frame plan: what Context::record does for a frame, decided from the effect settings and the frame's
// inputs before anything is recorded (docs/frame-plan.md). A host with its own render graph schedules
// postfx from it; tests assert it.
//
// Resource names: the host's images are "host.color", "host.depth", "host.output" (FrameInfo::output),
// "host.shadow_map" and "host.noise" (FogNoiseSettings::hostTexture); postfx's own resources are
// "<effect>.<name>" ("fog.noise", "fog.scatter", "fog.uniforms", ...).
#pragma once

#include <postfx/export.h>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace postfx {

struct PlannedPass {
    std::string name;                 // "fog.raymarch": the name Context::readPassTimings reports
    std::string effect;               // "fog"; "postfx" for the context's own passes
    std::vector<std::string> reads;   // resources the pass reads
    std::vector<std::string> writes;  // resources the pass writes
    uint32_t groups[3] = {0, 0, 0};   // workgroups dispatched (x, y, z)
};

struct PlannedResource {
    std::string name;    // "fog.noise"
    std::string effect;  // "fog"
    // Device memory of its data [bytes]: texels × bytes per texel for images, the size of buffers. A
    // driver's allocation may round this up; postfx allocates nothing else per effect.
    uint64_t bytes = 0;
    // Its contents are carried from one frame to the next (a temporal history, docs/temporal.md): a
    // host's render graph must keep it, unaliased, between postfx's frames.
    bool history = false;
    // A persistent image (a LUT, a noise texture) built in an earlier frame whose inputs did not change:
    // no pass of this frame writes it, the frame only reads it (docs/frame-plan.md).
    bool cached = false;
    // The setting that sizes it, as a settings-table key with the effect's prefix ("froxel_fog.grid",
    // "atmosphere.sky_view_lut_size"); empty for one sized by the color extent or fixed.
    std::string sizedBy;
};

struct POSTFX_API FramePlan {
    std::vector<PlannedPass> passes;         // in recording order
    std::vector<PlannedResource> resources;  // every resource postfx holds after recording the frame
    // Inputs postfx uses other than as given, where the documentation says it does rather than refusing
    // them (a camera below the ground draws the sky from the ground): one line each, naming the field.
    // record() also says each once through ContextCreateInfo::messageCallback (Warning) in the first
    // frame that has it.
    std::vector<std::string> adjusted;

    uint64_t totalBytes() const;                           // sum of resources[].bytes
    bool reads(std::string_view resource) const;           // some pass reads it
    bool writes(std::string_view resource) const;          // some pass writes it
    const PlannedPass* pass(std::string_view name) const;  // null when the frame has no such pass
};

}  // namespace postfx
