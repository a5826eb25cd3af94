#include "instrument/plugin/SchellengDiagram.h"

#include <cmath>

#include "instrument/plugin/StringLane.h"

namespace rosin::plugin
{

namespace
{
float logPosition(float value, float lo, float hi)
{
    return std::log(value / lo) / std::log(hi / lo);
}
} // namespace

float SchellengDiagram::effectiveDeltaMu(float muStatic, float muSlip)
{
    const float delta = muSlip > 0.0f && muStatic > muSlip ? muStatic - muSlip : 1.2f - 0.35f;
    return juce::jlimit(0.1f, 1.5f, delta);
}

float SchellengDiagram::maximumForce(const State& s, float beta)
{
    return 2.0f * s.impedance * s.bowSpeed / (beta * s.deltaMu);
}

float SchellengDiagram::minimumForce(const State& s, float beta)
{
    return s.impedance * s.impedance * s.bowSpeed * s.conductance / (2.0f * beta * beta * s.deltaMu);
}

void SchellengDiagram::setState(const State& state)
{
    state_ = state;
    if (state.bowing)
    {
        trail_[static_cast<std::size_t>(trailHead_)] = {state.beta, state.force};
        trailHead_ = (trailHead_ + 1) % kTrail;
        trailCount_ = juce::jmin(trailCount_ + 1, kTrail);
    }
    repaint();
}

juce::Rectangle<float> SchellengDiagram::plotArea() const
{
    return getLocalBounds()
        .toFloat()
        .withTrimmedLeft(46.0f)
        .withTrimmedBottom(34.0f)
        .withTrimmedTop(40.0f)
        .withTrimmedRight(12.0f);
}

juce::Point<float> SchellengDiagram::toScreen(juce::Rectangle<float> plot, float beta, float force) const
{
    return {plot.getX() + plot.getWidth() * logPosition(beta, kBetaMin, kBetaMax),
            plot.getBottom() - plot.getHeight() * logPosition(force, kForceMin, kForceMax)};
}

void SchellengDiagram::paint(juce::Graphics& g)
{
    const auto& lf = getLookAndFeel();
    const auto text = lf.findColour(juce::Label::textColourId);
    const auto background = lf.findColour(juce::ResizableWindow::backgroundColourId);
    g.setColour(background.brighter(0.08f));
    g.fillRoundedRectangle(getLocalBounds().toFloat().reduced(2.0f), 6.0f);

    g.setColour(text);
    g.setFont(juce::Font(15.0f, juce::Font::bold));
    g.drawText("Schelleng diagram", getLocalBounds().removeFromTop(22).withTrimmedLeft(10),
               juce::Justification::centredLeft);
    g.setFont(juce::Font(12.0f));
    g.setColour(text.withAlpha(0.75f));
    g.drawText(state_.title + "   v_b " + juce::String(state_.bowSpeed, 3) + " m/s   " +
                   juce::String::fromUTF8("\xce\x94\xce\xbc ") + juce::String(state_.deltaMu, 2) + "   Z0 " +
                   juce::String(state_.impedance, 3) + " kg/s",
               getLocalBounds().removeFromTop(40).withTrimmedTop(20).withTrimmedLeft(10),
               juce::Justification::centredLeft);

    const auto plot = plotArea();
    g.setColour(background.darker(0.25f));
    g.fillRect(plot);

    // Grid and tick labels.
    g.setFont(juce::Font(11.0f));
    for (float f : {0.1f, 0.2f, 0.5f, 1.0f, 2.0f, 3.0f})
    {
        const float y = toScreen(plot, kBetaMin, f).y;
        g.setColour(text.withAlpha(0.12f));
        g.drawHorizontalLine(juce::roundToInt(y), plot.getX(), plot.getRight());
        g.setColour(text.withAlpha(0.7f));
        g.drawText(juce::String(f, f < 1.0f ? 1 : 0),
                   juce::Rectangle<float>(plot.getX() - 40.0f, y - 7.0f, 36.0f, 14.0f),
                   juce::Justification::centredRight);
    }
    for (float b : {0.02f, 0.05f, 0.1f, 0.2f, 0.3f})
    {
        const float x = toScreen(plot, b, kForceMin).x;
        g.setColour(text.withAlpha(0.12f));
        g.drawVerticalLine(juce::roundToInt(x), plot.getY(), plot.getBottom());
        g.setColour(text.withAlpha(0.7f));
        g.drawText(juce::String(b, 2),
                   juce::Rectangle<float>(x - 20.0f, plot.getBottom() + 2.0f, 40.0f, 14.0f),
                   juce::Justification::centred);
    }
    g.setColour(text.withAlpha(0.85f));
    g.drawText(juce::String::fromUTF8("bow position \xce\xb2 (log)"),
               juce::Rectangle<float>(plot.getX(), plot.getBottom() + 16.0f, plot.getWidth(), 16.0f),
               juce::Justification::centred);
    {
        juce::Graphics::ScopedSaveState save(g);
        const auto label = juce::Rectangle<float>(0.0f, 0.0f, plot.getHeight(), 14.0f);
        g.addTransform(juce::AffineTransform::rotation(-juce::MathConstants<float>::halfPi)
                           .translated(4.0f, plot.getCentreY() + plot.getHeight() * 0.5f));
        g.drawText("bow force F (N, log)", label, juce::Justification::centred);
    }

    if (state_.impedance > 0.0f && state_.bowSpeed > 0.0f)
    {
        juce::Graphics::ScopedSaveState save(g);
        g.reduceClipRegion(plot.toNearestInt());
        juce::Path fmax, fmin, region;
        constexpr int kSteps = 64;
        for (int i = 0; i <= kSteps; ++i)
        {
            const float beta = kBetaMin * std::pow(kBetaMax / kBetaMin, static_cast<float>(i) / kSteps);
            // Clamp far off-plot values so the paths stay finite and well-conditioned.
            const float hi = juce::jlimit(kForceMin * 0.1f, kForceMax * 10.0f, maximumForce(state_, beta));
            const float lo = juce::jlimit(kForceMin * 0.1f, kForceMax * 10.0f, minimumForce(state_, beta));
            const auto a = toScreen(plot, beta, hi), b = toScreen(plot, beta, lo);
            i == 0 ? fmax.startNewSubPath(a) : fmax.lineTo(a);
            i == 0 ? fmin.startNewSubPath(b) : fmin.lineTo(b);
        }
        // The playable wedge between the two limits.
        region = fmax;
        for (int i = kSteps; i >= 0; --i)
        {
            const float beta = kBetaMin * std::pow(kBetaMax / kBetaMin, static_cast<float>(i) / kSteps);
            region.lineTo(toScreen(
                plot, beta, juce::jlimit(kForceMin * 0.1f, kForceMax * 10.0f, minimumForce(state_, beta))));
        }
        region.closeSubPath();
        g.setColour(juce::Colour(0xff4caf50).withAlpha(0.12f));
        g.fillPath(region);
        g.setColour(juce::Colour(0xffef5350));
        g.strokePath(fmax, juce::PathStrokeType(2.0f));
        juce::Path dashed;
        const float dashes[] = {6.0f, 4.0f};
        juce::PathStrokeType(1.6f).createDashedStroke(dashed, fmin, dashes, 2);
        g.setColour(juce::Colour(0xff64b5f6));
        g.fillPath(dashed);

        // The musical mapping's dynamics path, pp (small) to ff (large).
        if (state_.pathPoints > 1)
        {
            juce::Path path;
            for (int k = 0; k < state_.pathPoints; ++k)
            {
                const auto p = state_.path[static_cast<std::size_t>(k)];
                const auto s = toScreen(plot, juce::jlimit(kBetaMin, kBetaMax, p.x),
                                        juce::jlimit(kForceMin * 0.1f, kForceMax * 10.0f, p.y));
                k == 0 ? path.startNewSubPath(s) : path.lineTo(s);
                const float r =
                    1.5f + 3.0f * static_cast<float>(k) / static_cast<float>(state_.pathPoints - 1);
                g.setColour(juce::Colour(0xffffca28));
                g.fillEllipse(s.x - r, s.y - r, 2.0f * r, 2.0f * r);
            }
            g.setColour(juce::Colour(0xffffca28).withAlpha(0.8f));
            g.strokePath(path, juce::PathStrokeType(1.5f));
        }

        // The trail, oldest faintest, then the current point.
        for (int k = 0; k < trailCount_; ++k)
        {
            const int index = (trailHead_ - trailCount_ + k + kTrail) % kTrail;
            const auto p = trail_[static_cast<std::size_t>(index)];
            const auto s = toScreen(plot, juce::jlimit(kBetaMin, kBetaMax, p.x),
                                    juce::jlimit(kForceMin, kForceMax, p.y));
            g.setColour(text.withAlpha(0.08f + 0.3f * static_cast<float>(k) / kTrail));
            g.fillEllipse(s.x - 2.5f, s.y - 2.5f, 5.0f, 5.0f);
        }
    }
    const auto point = toScreen(plot, juce::jlimit(kBetaMin, kBetaMax, state_.beta),
                                juce::jlimit(kForceMin, kForceMax, state_.force));
    // The ring takes the regime's colour (StringLane's), so the point says what the string is doing there.
    g.setColour(state_.bowing ? StringLane::regimeColour(state_.regime) : text.withAlpha(0.4f));
    g.fillEllipse(point.x - 7.0f, point.y - 7.0f, 14.0f, 14.0f);
    g.setColour(state_.bowing ? juce::Colours::white : text.withAlpha(0.4f));
    g.drawEllipse(point.x - 7.0f, point.y - 7.0f, 14.0f, 14.0f, 2.0f);
    g.fillEllipse(point.x - 2.5f, point.y - 2.5f, 5.0f, 5.0f);

    // Legend.
    // Bottom right: large beta at low force, where the point seldom goes.
    auto legend =
        plot.reduced(8.0f).removeFromBottom(state_.pathPoints > 1 ? 50.0f : 34.0f).removeFromRight(150.0f);
    g.setColour(background.darker(0.25f).withAlpha(0.85f));
    g.fillRect(legend.expanded(4.0f, 2.0f));
    g.setFont(juce::Font(11.5f));
    g.setColour(juce::Colour(0xffef5350));
    g.fillRect(legend.getX(), legend.getY() + 7.0f, 18.0f, 2.0f);
    g.setColour(text);
    g.drawText("F_max (sticking limit)", legend.removeFromTop(16.0f).withTrimmedLeft(24.0f),
               juce::Justification::centredLeft);
    g.setColour(juce::Colour(0xff64b5f6));
    for (float x = 0.0f; x < 18.0f; x += 7.0f)
        g.fillRect(legend.getX() + x, legend.getY() + 7.0f, 4.0f, 2.0f);
    g.setColour(text);
    g.drawText("F_min (Schelleng)", legend.removeFromTop(16.0f).withTrimmedLeft(24.0f),
               juce::Justification::centredLeft);
    if (state_.pathPoints > 1)
    {
        g.setColour(juce::Colour(0xffffca28));
        g.fillEllipse(legend.getX() + 6.0f, legend.getY() + 4.0f, 7.0f, 7.0f);
        g.setColour(text);
        g.drawText("dynamics pp-ff", legend.removeFromTop(16.0f).withTrimmedLeft(24.0f),
                   juce::Justification::centredLeft);
    }
}

} // namespace rosin::plugin
