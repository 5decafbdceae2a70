// Cloud settings the clouds' tests share (the model's in double and the GPU's).
#pragma once

#include <postfx/context.h>

namespace test {

// A flat homogeneous layer (noise off, coverage 1) between 1000 and 2000 m of σt = 0.002 /m: optical depth
// 2 straight up.
inline postfx::CloudSettings homogeneousLayer() {
    postfx::CloudSettings s;
    s.enabled = true;
    s.noise.enabled = false;
    s.coverage = 1.0f;
    s.bottomHeight = 1000.0f;
    s.topHeight = 2000.0f;
    s.density = 0.002f;
    s.resolutionScale = 1.0f;  // every pixel its own ray, one frame (the closed forms are per pixel)
    s.temporal.enabled = false;
    return s;
}

// Noisy clouds (small textures) marched finely without jitter, for comparisons with the reference: what
// remains is the model's agreement and float precision.
inline postfx::CloudSettings finelyMarchedNoisyClouds() {
    postfx::CloudSettings s;
    s.enabled = true;
    s.coverage = 0.6f;
    s.noise.baseSize = 32;
    s.noise.detailSize = 16;
    s.steps = 256;
    s.lightSteps = 32;
    s.maxDistance = 30000.0f;
    s.jitter = false;
    s.resolutionScale = 1.0f;
    s.temporal.enabled = false;
    return s;
}

}  // namespace test
