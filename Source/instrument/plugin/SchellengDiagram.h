#pragma once
// A small Schelleng diagram for the sounding string: log bow force (0.1-3 N) against log beta (0.02-0.3),
// the maximum bow force F_max = 2 Z0 v_b / (beta (mu_s - mu_d)) (solid), the minimum bow force
// F_min = Z0^2 v_b G / (2 beta^2 (mu_s - mu_d)) (Schelleng's, with G the bridge conductance that stands for
// the losses: RosinProcessor's schellengConductance; dashed), and the current (beta, force) point with a
// short trail, and with the musical mapping the dynamics path pp-ff the player follows inside the band
// (player::DynamicsPath). mu_s is the law's static coefficient at the current force, mu_d the mean sliding
// coefficient measured while slipping; without a measurement (or for laws without a static peak) the
// classical curve's 1.2 - 0.35 stands in, and the difference is kept within 0.1..1.5 so the lines stay on the
// plot.
#include <array>

#include <juce_gui_basics/juce_gui_basics.h>

#include "instrument/plugin/StringTelemetry.h"

namespace rosin::plugin
{

class SchellengDiagram : public juce::Component
{
  public:
    static constexpr float kForceMin = 0.1f, kForceMax = 3.0f;
    static constexpr float kBetaMin = 0.02f, kBetaMax = 0.3f;

    struct State
    {
        juce::String title;       ///< e.g. "string II (D3)"
        float impedance = 0.0f;   ///< Z0, kg/s
        float bowSpeed = 0.1f;    ///< |v_b| for the limit lines, m/s
        float conductance = 0.0f; ///< G, s/kg
        float deltaMu = 0.85f;    ///< mu_s - mu_d
        float beta = 0.1f;        ///< current point
        float force = 1.0f;       ///< current point, N
        bool bowing = false;      ///< the point is live
        Regime regime = Regime::NoSlip;
        /// The musical mapping's dynamics path for this string, pp to ff at the current bow pressure, as
        /// (beta, force) points; none with the lab mapping.
        std::array<juce::Point<float>, 11> path{};
        int pathPoints = 0;
    };

    /// mu_s - mu_d as the diagram uses it (see above).
    static float effectiveDeltaMu(float muStatic, float muSlip);
    static float maximumForce(const State& s, float beta);
    static float minimumForce(const State& s, float beta);

    void setState(const State& state);
    const State& state() const noexcept { return state_; }
    void paint(juce::Graphics& g) override;

  private:
    juce::Rectangle<float> plotArea() const;
    juce::Point<float> toScreen(juce::Rectangle<float> plot, float beta, float force) const;

    State state_;
    static constexpr int kTrail = 24;
    std::array<juce::Point<float>, kTrail> trail_{}; // (beta, force)
    int trailCount_ = 0, trailHead_ = 0;
};

} // namespace rosin::plugin
