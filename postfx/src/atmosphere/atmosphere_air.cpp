// The atmosphere's side of common/air.h: the air other effects' references read, from the reference's
// tables (atmosphere_reference.h, atmosphere_orders.h).
#include "common/air.h"

#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_reference.h"

namespace postfx::atmosphere {
namespace {

class TableAir final : public common::Air {
public:
    explicit TableAir(const AtmosphereSettings& settings)
        : transmittance_(sharedTransmittanceTable(modelFrom(settings))) {}

    glm::dvec3 sunTransmittance(const glm::dvec3& world, const glm::dvec3& toSun,
                                bool liftAboveGround) const override {
        const Model& m = transmittance_->model();
        const glm::dvec3 p = planetCentred(m, world);
        return transmittance_->sun(liftAboveGround ? clampAboveGround(m, p) : p, toSun);
    }

    Segment viewSegment(const glm::dvec3& direction, double distance) const override {
        ViewRayOptions o = view_;
        o.maxDistance = distance;
        const ViewRayResult r = integrateViewRay(transmittance_->model(), origin_, direction, sun_, o);
        return {r.luminance, r.transmittance};
    }

    // For view segments: the camera, the sun and the multiple scattering of `settings`.
    void setView(const AtmosphereSettings& settings, const SunInput& sun, const glm::dvec3& camera,
                 uint32_t steps) {
        const Model& m = transmittance_->model();
        if (settings.multipleScattering == AtmosphereMultipleScattering::Hillaire) psi_ = sharedPsiTable(m);
        if (settings.multipleScattering == AtmosphereMultipleScattering::Orders)
            orders_ = sharedOrdersTable(m, coarseOrdersOptions());
        sun_.toSun = glm::normalize(glm::dvec3(sun.toSun));
        sun_.illuminance = glm::dvec3(sun.illuminance);
        view_.steps = steps;
        view_.multipleScattering = settings.multipleScattering != AtmosphereMultipleScattering::Off;
        view_.transmittanceTable = transmittance_.get();
        view_.psiTable = psi_.get();
        view_.ordersTable = orders_.get();
        view_.throughGround = true;
        origin_ = clampAboveGround(m, planetCentred(m, camera));
    }

private:
    std::shared_ptr<const TransmittanceTable> transmittance_;
    std::shared_ptr<const PsiTable> psi_;
    std::shared_ptr<const OrdersTable> orders_;
    Sun sun_;
    ViewRayOptions view_;
    glm::dvec3 origin_{0.0};
};

}  // namespace
}  // namespace postfx::atmosphere

namespace postfx::common {

std::shared_ptr<const Air> makeAir(const AtmosphereSettings& settings) {
    return std::make_shared<atmosphere::TableAir>(settings);
}

std::shared_ptr<const Air> makeViewAir(const AtmosphereSettings& settings, const SunInput& sun,
                                       const glm::dvec3& camera, uint32_t steps) {
    auto air = std::make_shared<atmosphere::TableAir>(settings);
    air->setView(settings, sun, camera, steps);
    return air;
}

}  // namespace postfx::common
