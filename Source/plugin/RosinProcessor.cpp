#include "RosinProcessor.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "gesture/MidiBytes.h"

namespace rosin::plugin
{

namespace
{
constexpr const char* kDefaultProgram = "cello-plastic";
constexpr double kGainSmoothingSeconds = 0.01;
const juce::Identifier kStateType{"RosinState"};
} // namespace

RosinProcessor::RosinProcessor()
    : juce::AudioProcessor(BusesProperties().withOutput("Output", juce::AudioChannelSet::stereo(), true)),
      state_(*this, nullptr, kStateType, createParameterLayout()), reader_(state_),
      programs_(loadFactoryPrograms())
{
    setCurrentProgram(findProgram(programs_, kDefaultProgram));
    startTimerHz(20);
}

RosinProcessor::~RosinProcessor()
{
    stopTimer();
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
        engine->openFrequencies[static_cast<std::size_t>(i)] = engine->instrument.openFrequency(i);
    return engine;
}

void RosinProcessor::prepareToPlay(double sampleRate, int)
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    sampleRate_ = sampleRate;
    const InstrumentKey key = reader_.readKey();
    slot_.installNow(buildEngine(key, programGeneration_));
    lastBuiltKey_ = key;
    lastBuiltGeneration_ = programGeneration_;
    prepared_ = true;

    const Engine& engine = *slot_.active();
    controller_.prepare(engine.openFrequencies.data(), engine.instrument.stringCount(), sampleRate);
    controllerSerial_ = engine.serial;
    gain_.prepare(kGainSmoothingSeconds, sampleRate);
    resetRequested_ = false;
    runawayResets_ = 0;
    nonFiniteSamples_ = 0;
}

void RosinProcessor::releaseResources()
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    slot_.installNow(nullptr);
    prepared_ = false;
    controllerSerial_ = -1;
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
    if (engine->serial != controllerSerial_)
    {
        // A rebuilt instrument starts at rest; the gesture continues unless the strings changed (instrument
        // switch), where the controller is re-prepared (fixed-size state: no allocation).
        bool sameStrings = controllerSerial_ >= 0 && controller_.stringCount() == strings;
        for (int i = 0; sameStrings && i < strings; ++i)
            sameStrings =
                controller_.openFrequency(i) == engine->openFrequencies[static_cast<std::size_t>(i)];
        if (!sameStrings)
            controller_.prepare(engine->openFrequencies.data(), strings, engine->sampleRate);
        controllerSerial_ = engine->serial;
    }
    if (resetRequested_.exchange(false))
    {
        instrument.reset();
        controller_.reset();
    }

    const ParameterSnapshot snapshot = reader_.read(strings);
    controller_.setParameters(snapshot.gesture);

    float* out = buffer.getWritePointer(0);
    auto event = midi.cbegin();
    const auto end = midi.cend();
    int runaways = 0, nonFinite = 0;
    for (int i = 0; i < numSamples; ++i)
    {
        // Events at their sample: the output does not depend on how the host cuts blocks.
        for (; event != end && (*event).samplePosition <= i; ++event)
        {
            const auto m = *event;
            gesture::GestureEvent e;
            if (gesture::decodeMidi(m.data, m.numBytes, i, e))
                controller_.handleEvent(e);
        }
        controller_.next(inputs_.data());
        double y = instrument.step(inputs_.data(), outputs_.data());
        if (instrument.recoveredFromRunaway())
            ++runaways;
        y *= gain_.process(snapshot.outputGain);
        if (!std::isfinite(y))
        {
            y = 0.0;
            ++nonFinite;
        }
        out[i] = static_cast<float>(std::clamp(y, -kOutputClamp, kOutputClamp));
    }
    for (; event != end; ++event) // events stamped past the block's end (malformed host data)
    {
        const auto m = *event;
        gesture::GestureEvent e;
        if (gesture::decodeMidi(m.data, m.numBytes, numSamples, e))
            controller_.handleEvent(e);
    }
    for (int c = 1; c < buffer.getNumChannels(); ++c)
        buffer.copyFrom(c, 0, buffer, 0, 0, numSamples);
    if (runaways > 0)
        runawayResets_.fetch_add(runaways, std::memory_order_relaxed);
    if (nonFinite > 0)
        nonFiniteSamples_.fetch_add(nonFinite, std::memory_order_relaxed);
}

juce::AudioProcessorEditor* RosinProcessor::createEditor()
{
    return new juce::GenericAudioProcessorEditor(*this);
}

void RosinProcessor::getStateInformation(juce::MemoryBlock& destData)
{
    juce::ValueTree tree = state_.copyState();
    tree.setProperty("stateVersion", kStateVersion, nullptr);
    tree.setProperty("program", getProgramName(currentProgram_), nullptr);
    if (auto xml = tree.createXml())
        copyXmlToBinary(*xml, destData);
}

void RosinProcessor::setStateInformation(const void* data, int sizeInBytes)
{
    const auto xml = getXmlFromBinary(data, sizeInBytes);
    if (xml == nullptr || !xml->hasTagName(kStateType))
        return;
    juce::ValueTree tree = juce::ValueTree::fromXml(*xml);
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
    state_.replaceState(tree);
}

} // namespace rosin::plugin
