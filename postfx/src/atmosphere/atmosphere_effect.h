// The sky and atmosphere behind the effect boundary (docs/effects/atmosphere.md): its settings' checks
// and its declaration of a frame: the uniforms, the four LUTs (persistent images, each rebuilt only when
// what it depends on changed: core/frame_graph.h's build keys) and the apply pass that draws the sky on
// pixels without geometry and the aerial perspective on the others. The uniforms and LUTs other effects
// read are declared under the handles of common/shared_resources.h.
#pragma once

#include "core/effect.h"
#include "core/frame_graph.h"
#include "core/gpu.h"

#include <glm/glm.hpp>

namespace postfx::atmosphere {

// The scattering orders' two working images (order n and n + 1), transient, while the LUT is built.
inline constexpr core::ResourceId kScatteringOrderA{"atmosphere.scattering_order_a"};
inline constexpr core::ResourceId kScatteringOrderB{"atmosphere.scattering_order_b"};
inline constexpr core::ResourceId kSkyViewLut{"atmosphere.sky_view"};  // rgba16f 2D, 2 layers

// The luminance LUTs' storage scale (AtmosphereUniforms::skyView.w): the multiple-scattering, sky-view and
// aerial-perspective LUTs hold luminance per unit illuminance times this, 1 / the largest vertical
// scattering optical depth of a channel, so their texels stay normal half floats (about 0.01 to 1) for
// an atmosphere 1e-4 or 1e3 times as dense as Earth's; in [1e-3, 1e6].
double lutStorageScale(const AtmosphereSettings& settings);

// The scattering-orders LUT's storage scale (AtmosphereUniforms::radii.w): max(1, lutStorageScale). Its
// values are radiance per unit illuminance, about τ/4π in a thin atmosphere and down to about 1/τ near the
// ground of a thick one.
double ordersStorageScale(const AtmosphereSettings& settings);

// The camera and sun a view-dependent LUT was built for (docs/effects/atmosphere.md#frame-plan).
struct LutView {
    bool valid = false;
    uint64_t settingsKey = 0;  // the settings it was built with (media, sizes, steps)
    glm::dvec3 camera{0.0};    // planet-centred camera, clamped above the ground [m]
    glm::dvec3 toSun{0.0, 1.0, 0.0};
    glm::dmat4 viewToClip{1.0};  // camera-relative world -> clip (aerial perspective only)
};

class AtmosphereEffect final : public core::Effect {
public:
    explicit AtmosphereEffect(const core::Gpu& gpu);

    const char* name() const override { return "atmosphere"; }
    Status validate(const FrameInfo& frame) const override;
    bool active(const FrameInfo& frame) const override { return frame.atmosphere.enabled; }
    Status declare(core::FrameBuilder& builder) const override;
    void recorded(const FrameInfo& frame, bool active) override;
    void adjusted(const FrameInfo& frame, std::vector<std::string>& out) const override;

    // The views this frame's sky-view and aerial-perspective LUTs are (or stay) built for.
    struct Views {
        LutView skyView, aerial;
    };
    Views views(const FrameInfo& frame) const;

private:
    Views built_;
};

}  // namespace postfx::atmosphere
