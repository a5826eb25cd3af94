#pragma once
// What every thermal friction law carries (plastic, viscous, modified): the contact's heat balance, the
// calibrated table of its material property against temperature, and the power and sliding speed of the
// previous sample, which the predictor uses (Woodhouse's order, [Notes §2.5]).
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/ThermalCalibration.h"

namespace rosin::physics
{

class ThermalContact
{
  public:
    explicit ThermalContact(const ContactParameters& contact) : contact_(contact) {}

    /// Off the audio thread: fits the heat model for the rig contact and calibrates `quantity` at this rate.
    void prepare(double sampleRate, CalibrationQuantity quantity);
    void reset() noexcept;
    bool prepared() const noexcept { return prepared_; }

    /// Contact temperature rise (K) this sample would reach with the previous sample's power (predictor).
    double predict(double bowForce) const noexcept;
    /// ... with the power and speed of a trial solution (corrector).
    double predict(const JunctionSolution& trial, double bowForce) const noexcept;
    /// Advance the heat balance with this sample's solution.
    void commit(const JunctionSolution& solution, double bowForce) noexcept;
    /// Advance the heat balance with the bow lifted (HeatBalance::open); the next predictor starts from no
    /// power.
    void open() noexcept;

    /// The calibrated property at rise T, read at T + ambientOffset (a warmer rosin starts further up).
    double property(double temperatureRise) const noexcept
    {
        return table_.lookup(temperatureRise + contact_.ambientOffset);
    }
    /// Real contact area pi a(Fb)^2 of the rig, m^2.
    double area(double bowForce) const noexcept;

    double temperature() const noexcept { return heat_.temperature(); }
    const ContactParameters& contact() const noexcept { return contact_; }
    const HeatBalance& heat() const noexcept { return heat_; }
    const ThermalCalibration& calibration() const noexcept { return table_; }

  private:
    ContactParameters contact_;
    HeatBalance heat_;
    ThermalCalibration table_;
    double previousPower_ = 0.0; ///< W, |f dv| of the previous sample
    double previousSpeed_ = 0.0; ///< m/s, |dv| of the previous sample
    bool prepared_ = false;
    // area() for the last force asked (the laws ask every sample, and the radius costs a root); a cache.
    mutable double areaForce_ = -1.0, area_ = 0.0;
};

} // namespace rosin::physics
