#include "RosinProcessor.h"

#include "SavedState.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <thread>

#include "RosinEditor.h"
#include "gesture/MidiBytes.h"

namespace rosin::plugin
{

namespace
{
constexpr const char* kDefaultProgram = "cello-plastic";
constexpr double kGainSmoothingSeconds = 0.01;
const juce::Identifier kStateType{"RosinState"};

// Loss at the string's ends as a bridge conductance G (s/kg), for Schelleng's F_min = Z0^2 v_b G /
// (2 beta^2 (mu_s - mu_d)): the body's mean real admittance over the string's first ten harmonics, plus the
// string's own damping of its fundamental expressed as the bridge conductance that would lose as much per
// period (reflection 1 - 2 Z0 G = exp(-pi eta) => G = pi eta / (2 Z0)). A simple estimate, for display.
double schellengConductance(const physics::InstrumentConfig& config, std::size_t i)
{
    const physics::StringParameters& string = config.strings[i];
    const double f0 = string.fundamental();
    double body = 0.0;
    constexpr int kPoints = 32;
    for (int k = 0; k < kPoints; ++k)
        body += config.body.admittance(f0 * std::pow(10.0, k / (kPoints - 1.0))).real();
    body = std::max(0.0, body / kPoints);
    const double z0 = string.impedance();
    const double eta = string.lossFactor(1, string.length, false);
    return body + (z0 > 0.0 ? 3.14159265358979 * eta / (2.0 * z0) : 0.0);
}
} // namespace

RosinProcessor::RosinProcessor()
    : juce::AudioProcessor(BusesProperties().withOutput("Output", juce::AudioChannelSet::stereo(), true)),
      state_(*this, nullptr, kStateType, createParameterLayout()), reader_(state_),
      programs_(loadFactoryPrograms()), bypass_(state_.getRawParameterValue(ids::bypass))
{
    setCurrentProgram(findProgram(programs_, kDefaultProgram));
    keyboardState_.addListener(&keyboardQueue_);
    startTimerHz(20);
}

RosinProcessor::~RosinProcessor()
{
    // A host may destroy the processor off the message thread (JUCE's LV2 wrapper runs its own message
    // thread) while the timer callback is building an engine there: stopTimer() does not wait for it, so wait
    // here before the members it uses go away.
    closing_ = true;
    stopTimer();
    keyboardState_.removeListener(&keyboardQueue_);
    while (timerCallbacksRunning_.load() > 0)
        std::this_thread::yield();
}

void RosinProcessor::timerCallback()
{
    timerCallbacksRunning_.fetch_add(1);
    if (!closing_.load())
        serviceEngineBuilds();
    timerCallbacksRunning_.fetch_sub(1);
}

const juce::String RosinProcessor::getProgramName(int index)
{
    if (index < 0 || index >= getNumPrograms())
        return {};
    return programs_[static_cast<std::size_t>(index)].name;
}

void RosinProcessor::setParameterValue(const char* id, float value)
{
    if (auto* p = state_.getParameter(id))
        p->setValueNotifyingHost(p->convertTo0to1(value));
}

void RosinProcessor::setCurrentProgram(int index)
{
    if (index < 0 || index >= getNumPrograms())
        return;
    const config::Preset& preset = programs_[static_cast<std::size_t>(index)].preset;
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        currentProgram_ = index;
        extras_.preset = preset;
        ++programGeneration_;
    }
    // The program's slow settings become parameter values, so a host sees and automates them.
    setParameterValue(ids::instrument, static_cast<float>(instrumentIndexForPreset(preset)));
    setParameterValue(ids::friction,
                      static_cast<float>(static_cast<int>(physics::frictionModelFromName(preset.friction))));
    setParameterValue(ids::body, preset.body == "rigid" ? 0.0f : 1.0f);
    setParameterValue(ids::ambientTemperature,
                      static_cast<float>(kCalibrationAmbientCelsius + preset.ambientOffset));
    setParameterValue(ids::beta, static_cast<float>(preset.beta));
    setParameterValue(ids::outputLevel,
                      static_cast<float>(preset.outputLevel.value_or(kDefaultOutputLevelDb)));
    if (preset.bodyResponse && !bodyResponse_.load(juce::File(*preset.bodyResponse)))
        std::cerr << "rosin: program " << preset.name << ": " << bodyResponse_.status() << "\n";
    else if (bodyResponse_.path().isNotEmpty())
        bodyResponse_.clear();
    if (!prepared_)
        publishIdleTelemetry();
}

bool RosinProcessor::setProgramByName(const std::string& name)
{
    for (int i = 0; i < getNumPrograms(); ++i)
        if (programs_[static_cast<std::size_t>(i)].name == name)
        {
            setCurrentProgram(i);
            return true;
        }
    return false;
}

std::unique_ptr<Engine> RosinProcessor::buildEngine(const InstrumentKey& key, int generation)
{
    auto engine = std::make_unique<Engine>();
    engine->key = key;
    engine->programGeneration = generation;
    engine->sampleRate = sampleRate_;
    engine->serial = nextSerial_++;
    physics::InstrumentConfig config;
    try
    {
        config = buildInstrumentConfig(key, extras_);
    }
    catch (const std::exception& e)
    {
        std::cerr << "rosin: program ignored: " << e.what() << "\n";
        config = buildInstrumentConfig(key, ProgramExtras{});
    }
    engine->instrument.prepare(config, sampleRate_);
    for (int i = 0;
         i < engine->instrument.stringCount() && i < static_cast<int>(engine->openFrequencies.size()); ++i)
    {
        const auto k = static_cast<std::size_t>(i);
        engine->openFrequencies[k] = engine->instrument.openFrequency(i);
        engine->impedances[k] = engine->instrument.config().strings[k].impedance();
        engine->bridgeConductances[k] = schellengConductance(engine->instrument.config(), k);
    }
    return engine;
}

void RosinProcessor::prepareToPlay(double sampleRate, int maximumExpectedSamplesPerBlock)
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    sampleRate_ = sampleRate;
    const InstrumentKey key = reader_.readKey();
    slot_.installNow(buildEngine(key, programGeneration_));
    lastBuiltKey_ = key;
    lastBuiltGeneration_ = programGeneration_;
    prepared_ = true;

    const Engine& engine = *slot_.active();
    performer_.prepare(engine.serial, engine.openFrequencies.data(), engine.instrument.stringCount(),
                       sampleRate);
    collectBodyResponse(); // a response set before is built in prepare, ready for the first block
    output_.prepare(sampleRate, kGainSmoothingSeconds, maximumExpectedSamplesPerBlock);
    setLatencySamples(output_.latencySamples());
    resetRequested_ = false;
    runawayResets_ = 0;
    nonFiniteSamples_ = 0;
}

void RosinProcessor::releaseResources()
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    slot_.installNow(nullptr);
    prepared_ = false;
    performer_.release();
}

void RosinProcessor::reset()
{
    // May come from the audio thread: only flag it; processBlock clears the state.
    resetRequested_ = true;
}

void RosinProcessor::serviceEngineBuilds()
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    slot_.collect();
    if (!prepared_)
        return;
    const InstrumentKey key = reader_.readKey();
    if (key == lastBuiltKey_ && programGeneration_ == lastBuiltGeneration_)
        return;
    lastBuiltKey_ = key;
    lastBuiltGeneration_ = programGeneration_;
    slot_.publish(buildEngine(key, programGeneration_));
}

bool RosinProcessor::isBusesLayoutSupported(const BusesLayout& layouts) const
{
    const auto out = layouts.getMainOutputChannelSet();
    return layouts.inputBuses.isEmpty() &&
           (out == juce::AudioChannelSet::mono() || out == juce::AudioChannelSet::stereo());
}

namespace
{
// The host's MIDI for one block, decoded as the performer reaches each event's sample (undecodable ones are
// skipped).
class MidiEvents final : public performer::EventSource
{
  public:
    explicit MidiEvents(const juce::MidiBuffer& midi) : next_(midi.cbegin()), end_(midi.cend()) {}
    bool next(int sample, gesture::GestureEvent& event) noexcept override
    {
        while (next_ != end_ && (*next_).samplePosition <= sample)
            if (decode(sample, event))
                return true;
        return false;
    }
    bool remaining(int sample, gesture::GestureEvent& event) noexcept override
    {
        while (next_ != end_)
            if (decode(sample, event))
                return true;
        return false;
    }

  private:
    bool decode(int sample, gesture::GestureEvent& event) noexcept
    {
        const auto m = *next_;
        ++next_;
        return gesture::decodeMidi(m.data, m.numBytes, sample, event);
    }
    juce::MidiBufferIterator next_, end_;
};

// Each sample through the output stage into the host's first channel.
class ToOutputStage final : public performer::SampleSink
{
  public:
    ToOutputStage(OutputStage& stage, const OutputSettings& settings, float* out) noexcept
        : stage_(stage), settings_(settings), out_(out)
    {
    }
    void take(int i, const physics::BowedInstrument& instrument, double bridgeForce) noexcept override
    {
        bool bad = false;
        out_[i] = stage_.sample(i, instrument, bridgeForce, settings_, bad);
        nonFinite += bad ? 1 : 0;
    }
    int nonFinite = 0;

  private:
    OutputStage& stage_;
    const OutputSettings& settings_;
    float* out_;
};
} // namespace

void RosinProcessor::processBlock(juce::AudioBuffer<float>& buffer, juce::MidiBuffer& midi)
{
    juce::ScopedNoDenormals noDenormals;
    const int numSamples = buffer.getNumSamples();
    buffer.clear();
    Engine* engine = slot_.acquire();
    if (engine == nullptr || buffer.getNumChannels() == 0)
        return;

    physics::BowedInstrument& instrument = engine->instrument;
    const int strings = instrument.stringCount();
    performer_.follow(engine->serial, engine->openFrequencies.data(), strings, engine->sampleRate);
    if (resetRequested_.exchange(false))
    {
        instrument.reset();
        performer_.reset();
        output_.reset();
    }

    const ParameterSnapshot snapshot = reader_.read(strings);
    performer_.beginBlock({snapshot.gesture, snapshot.intonationByEar});
    collectBodyResponse();
    // The on-screen keyboard's notes, at the block's first sample.
    keyboardQueue_.drain(
        [this](const std::uint8_t* bytes, int size)
        {
            gesture::GestureEvent e;
            if (gesture::decodeMidi(bytes, size, 0, e))
                performer_.handleEvent(e);
        });

    float* out = buffer.getWritePointer(0);
    MidiEvents events(midi);
    ToOutputStage sink(output_, snapshot.output, out);
    const int runaways = performer_.process(instrument, events, sink, numSamples);
    output_.finishBlock(out, numSamples, snapshot.output);
    const float bypassTarget = bypass_->load() >= 0.5f ? 0.0f : 1.0f;
    if (bypassTarget != 1.0f || bypassGain_ != 1.0f)
        buffer.applyGainRamp(0, 0, numSamples, bypassGain_, bypassTarget);
    bypassGain_ = bypassTarget;
    for (int c = 1; c < buffer.getNumChannels(); ++c)
        buffer.copyFrom(c, 0, buffer, 0, 0, numSamples);
    publishTelemetry(*engine);
    if (runaways > 0)
        runawayResets_.fetch_add(runaways, std::memory_order_relaxed);
    if (sink.nonFinite > 0)
        nonFiniteSamples_.fetch_add(sink.nonFinite, std::memory_order_relaxed);
}

void RosinProcessor::collectBodyResponse() noexcept
{
    responseHandoff_.collect([this](juce::AudioBuffer<float>&& response, double rate)
                             { output_.measured().use(std::move(response), rate); },
                             [this] { output_.measured().clear(); });
}

void RosinProcessor::publishIdleTelemetry()
{
    physics::InstrumentConfig config;
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        config = buildInstrumentConfig(reader_.readKey(), extras_);
    }
    const ParameterSnapshot snapshot = reader_.read(static_cast<int>(config.strings.size()));
    auto law = physics::makeFrictionLaw(config.friction, config.contact);
    law->prepare(sampleRate_);
    const int strings = std::min(static_cast<int>(config.strings.size()), Telemetry::kMaxStrings);
    telemetry_.stringCount.store(strings, std::memory_order_relaxed);
    for (int s = 0; s < strings; ++s)
    {
        const auto k = static_cast<std::size_t>(s);
        StringReadout r;
        r.openFrequency = r.frequency = static_cast<float>(config.strings[k].fundamental());
        r.impedance = static_cast<float>(config.strings[k].impedance());
        r.bridgeConductance = static_cast<float>(schellengConductance(config, k));
        r.bowForce = static_cast<float>(snapshot.gesture.bowForce);
        r.beta = static_cast<float>(snapshot.gesture.beta);
        r.bowVelocity = 0.0f;
        r.muStatic = static_cast<float>(law->staticCoefficient(snapshot.gesture.bowForce));
        telemetry_.strings[k].publish(r);
    }
}

void RosinProcessor::publishTelemetry(const Engine& engine) noexcept
{
    const int strings = std::min(engine.instrument.stringCount(), Telemetry::kMaxStrings);
    telemetry_.stringCount.store(strings, std::memory_order_relaxed);
    for (int s = 0; s < strings; ++s)
    {
        const auto k = static_cast<std::size_t>(s);
        const physics::BowInput& in = performer_.input(s);
        const physics::VoiceSample& out = performer_.output(s);
        StringReadout r;
        const lab::LiveRegimeMeter& meter = performer_.meter(s);
        r.regime = meter.regime();
        r.flybacksPerPeriod = meter.flybacksPerPeriod();
        r.slipsPerPeriod = meter.slipsPerPeriod();
        r.irregularity = meter.irregularity();
        r.stickFraction = meter.stickFraction();
        r.muSlip = meter.muSlip();
        r.openFrequency = static_cast<float>(engine.openFrequencies[k]);
        r.frequency =
            static_cast<float>(engine.openFrequencies[k] / (in.fingerRatio > 0.0 ? in.fingerRatio : 1.0));
        r.temperature = static_cast<float>(out.contactTemperature);
        r.bowForce = static_cast<float>(in.bowForce);
        r.beta = static_cast<float>(in.beta);
        r.bowVelocity = static_cast<float>(in.bowVelocity);
        r.impedance = static_cast<float>(engine.impedances[k]);
        r.bridgeConductance = static_cast<float>(engine.bridgeConductances[k]);
        r.muStatic = static_cast<float>(engine.instrument.voice(s).friction().staticCoefficient(in.bowForce));
        r.sticking = out.sticking;
        r.bowing = in.bowForce > 1e-3 && std::abs(in.bowVelocity) > 1e-4;
        telemetry_.strings[k].publish(r);
    }
}

juce::AudioProcessorEditor* RosinProcessor::createEditor()
{
    return new RosinEditor(*this);
}

juce::AudioProcessorParameter* RosinProcessor::getBypassParameter() const
{
    return state_.getParameter(ids::bypass);
}

void RosinProcessor::getStateInformation(juce::MemoryBlock& destData)
{
    juce::ValueTree tree = state_.copyState();
    tree.setProperty("stateVersion", kStateVersion, nullptr);
    tree.setProperty("program", getProgramName(currentProgram_), nullptr);
    bodyResponse_.save(tree);
    if (auto xml = tree.createXml())
        copyXmlToBinary(*xml, destData);
}

void RosinProcessor::setStateInformation(const void* data, int sizeInBytes)
{
    if (const auto problem = unparseableState(data, sizeInBytes))
    {
        std::cerr << "rosin: state not restored: " << *problem << "\n";
        return;
    }
    const auto xml = getXmlFromBinary(data, sizeInBytes);
    if (xml == nullptr || !xml->hasTagName(kStateType))
        return;
    juce::ValueTree tree = juce::ValueTree::fromXml(*xml);
    for (const auto& message : sanitiseParameterValues(tree, state_))
        std::cerr << "rosin: state: " << message << "\n";
    // Version 1 is the only format so far; later versions migrate here before replaceState.
    if (static_cast<int>(tree.getProperty("stateVersion", 0)) > kStateVersion)
        std::cerr << "rosin: state from a newer version; reading what is known\n";
    const int program = findProgram(programs_, tree.getProperty("program").toString().toStdString());
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        currentProgram_ = program;
        extras_.preset = programs_[static_cast<std::size_t>(program)].preset;
        ++programGeneration_;
    }
    tree.removeProperty("stateVersion", nullptr);
    tree.removeProperty("program", nullptr);
    bodyResponse_.restore(tree);
    state_.replaceState(tree);
    refreshHostValues(state_);
    if (!prepared_)
        publishIdleTelemetry();
}

} // namespace rosin::plugin
