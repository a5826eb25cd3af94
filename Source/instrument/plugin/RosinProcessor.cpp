#include "instrument/plugin/RosinProcessor.h"

#include "instrument/plugin/SavedState.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <thread>

#include "instrument/engine/MidiInput.h"
#include "instrument/player/MidiBytes.h"
#include "instrument/plugin/RosinEditor.h"

namespace rosin::plugin
{

namespace
{
const juce::Identifier kStateType{"RosinState"};
} // namespace

RosinProcessor::RosinProcessor()
    : juce::AudioProcessor(BusesProperties().withOutput("Output", juce::AudioChannelSet::stereo(), true)),
      state_(*this, nullptr, kStateType, createParameterLayout()), reader_(state_),
      programs_(engine::loadFactoryPrograms()), bypass_(state_.getRawParameterValue(ids::bypass))
{
    setCurrentProgram(engine::findProgram(programs_, engine::kDefaultProgramName));
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
        engine::setPlainValue(*p, value);
}

void RosinProcessor::setCurrentProgram(int index)
{
    if (index < 0 || index >= getNumPrograms())
        return;
    applyProgram(index, programs_[static_cast<std::size_t>(index)].preset, std::nullopt);
}

void RosinProcessor::applyProgram(int index, const config::Preset& preset, std::optional<ProgramFile> file)
{
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        currentProgram_ = index;
        extras_.preset = preset;
        programFile_ = std::move(file);
        ++programGeneration_;
    }
    // The program's slow settings become parameter values, so a host sees and automates them.
    for (const auto& [id, value] : engine::programParameterValues(preset))
        setParameterValue(id, value);
    if (preset.bodyResponse && !bodyResponse_.load(juce::File(*preset.bodyResponse)))
        std::cerr << "rosin: program " << preset.name << ": " << bodyResponse_.status() << "\n";
    else if (bodyResponse_.path().isNotEmpty())
        bodyResponse_.clear();
    if (!prepared_)
        publishIdleTelemetry();
}

bool RosinProcessor::loadProgramFile(const juce::File& file)
{
    auto read = readProgramFile(file);
    if (auto* error = std::get_if<std::string>(&read))
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        programFileStatus_ = *error;
        return false;
    }
    ProgramFile program = std::get<ProgramFile>(std::move(read));
    const config::Preset preset = program.preset;
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        programFileStatus_ = "program " + juce::String(preset.name) + " from " + program.path;
    }
    applyProgram(currentProgram_, preset, std::move(program));
    return true;
}

juce::String RosinProcessor::programFileStatus() const
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    return programFileStatus_;
}

juce::String RosinProcessor::programTitle() const
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    if (programFile_)
        return juce::String(programFile_->preset.name) + " (" +
               juce::File::createFileWithoutCheckingPath(programFile_->path).getFileName() + ")";
    return programs_[static_cast<std::size_t>(currentProgram_)].name;
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

void RosinProcessor::prepareToPlay(double sampleRate, int maximumExpectedSamplesPerBlock)
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    sampleRate_ = sampleRate;
    const engine::InstrumentKey key = reader_.readKey();
    slot_.installNow(engine::buildEngine(key, extras_, programGeneration_, nextSerial_++, sampleRate_));
    lastBuiltKey_ = key;
    lastBuiltGeneration_ = programGeneration_;
    prepared_ = true;

    collectBodyResponse(); // a response set before is built in prepare, ready for the first block
    player_.prepare(*slot_.active(), sampleRate, maximumExpectedSamplesPerBlock);
    setLatencySamples(player_.output().latencySamples());
    resetRequested_ = false;
    runawayResets_ = 0;
    nonFiniteSamples_ = 0;
}

void RosinProcessor::releaseResources()
{
    std::lock_guard<std::mutex> lock(builderMutex_);
    slot_.installNow(nullptr);
    prepared_ = false;
    player_.release();
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
    const engine::InstrumentKey key = reader_.readKey();
    if (key == lastBuiltKey_ && programGeneration_ == lastBuiltGeneration_)
        return;
    lastBuiltKey_ = key;
    lastBuiltGeneration_ = programGeneration_;
    slot_.publish(engine::buildEngine(key, extras_, programGeneration_, nextSerial_++, sampleRate_));
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
    // Offline, nothing waits for this block: a pending rebuild happens here rather than at the timer's next
    // tick, so an export renders the same on every run (and as `rosin render --midi` does).
    if (isNonRealtime())
        serviceEngineBuilds();
    Engine* active = slot_.acquire();
    if (active == nullptr || buffer.getNumChannels() == 0)
        return;

    player_.follow(*active);
    if (resetRequested_.exchange(false))
        player_.reset(*active);

    const engine::ParameterSnapshot snapshot = reader_.read(active->instrument.stringCount());
    player_.beginBlock(snapshot);
    collectBodyResponse();
    // The on-screen keyboard's notes, at the block's first sample.
    keyboardQueue_.drain(
        [this](const std::uint8_t* bytes, int size)
        {
            player::GestureEvent e;
            if (player::decodeMidi(bytes, size, 0, e))
                player_.performer().handleEvent(e);
        });

    float* out = buffer.getWritePointer(0);
    engine::MidiBufferEvents events(midi);
    const auto played = player_.play(*active, events, snapshot.output, out, numSamples);
    const float bypassTarget = bypass_->load() >= 0.5f ? 0.0f : 1.0f;
    if (bypassTarget != 1.0f || bypassGain_ != 1.0f)
        buffer.applyGainRamp(0, 0, numSamples, bypassGain_, bypassTarget);
    bypassGain_ = bypassTarget;
    for (int c = 1; c < buffer.getNumChannels(); ++c)
        buffer.copyFrom(c, 0, buffer, 0, 0, numSamples);
    publishTelemetry(*active);
    if (played.runawayResets > 0)
        runawayResets_.fetch_add(played.runawayResets, std::memory_order_relaxed);
    if (played.nonFinite > 0)
        nonFiniteSamples_.fetch_add(played.nonFinite, std::memory_order_relaxed);
}

void RosinProcessor::collectBodyResponse() noexcept
{
    responseHandoff_.collect([this](juce::AudioBuffer<float>&& response, double rate)
                             { player_.output().measured().use(std::move(response), rate); },
                             [this] { player_.output().measured().clear(); });
}

void RosinProcessor::publishIdleTelemetry()
{
    physics::InstrumentConfig config;
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        config = engine::buildInstrumentConfig(reader_.readKey(), extras_);
    }
    const engine::ParameterSnapshot snapshot = reader_.read(static_cast<int>(config.strings.size()));
    auto law = physics::makeFrictionLaw(config.friction, config.contact);
    law->prepare(sampleRate_);
    const auto limits = physics::frictionLimits(config.friction, config.contact, sampleRate_);
    const int strings = std::min(static_cast<int>(config.strings.size()), Telemetry::kMaxStrings);
    telemetry_.stringCount.store(strings, std::memory_order_relaxed);
    for (int s = 0; s < strings; ++s)
    {
        const auto k = static_cast<std::size_t>(s);
        StringReadout r;
        const player::PlayableBand band = engine::playableBand(config, k, limits);
        r.bandMuStatic = static_cast<float>(band.muStatic);
        r.bandMuDynamic = static_cast<float>(band.muDynamic);
        r.openFrequency = r.frequency = static_cast<float>(config.strings[k].fundamental());
        r.impedance = static_cast<float>(config.strings[k].impedance());
        r.bridgeConductance = static_cast<float>(engine::schellengConductance(config, k));
        const double force = snapshot.gesture.bowForce * engine::bowForceShare(config.strings[k].impedance());
        r.bowForce = static_cast<float>(force);
        r.beta = static_cast<float>(snapshot.gesture.beta);
        r.bowVelocity = 0.0f;
        r.muStatic = static_cast<float>(law->staticCoefficient(force));
        telemetry_.strings[k].publish(r);
    }
}

void RosinProcessor::publishTelemetry(const engine::Engine& engine) noexcept
{
    const int strings = std::min(engine.instrument.stringCount(), Telemetry::kMaxStrings);
    telemetry_.stringCount.store(strings, std::memory_order_relaxed);
    for (int s = 0; s < strings; ++s)
    {
        const auto k = static_cast<std::size_t>(s);
        const physics::BowInput& in = player_.performer().input(s);
        const physics::VoiceSample& out = player_.performer().output(s);
        StringReadout r;
        const analysis::LiveRegimeMeter& meter = player_.performer().meter(s);
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
        r.bandMuStatic = static_cast<float>(engine.bands[k].muStatic);
        r.bandMuDynamic = static_cast<float>(engine.bands[k].muDynamic);
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
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        if (programFile_)
            saveProgramFile(*programFile_, tree);
    }
    bodyResponse_.save(tree);
    if (auto xml = tree.createXml())
        copyXmlToBinary(*xml, destData);
}

void RosinProcessor::migrateState(juce::ValueTree& tree)
{
    // A state saved before the musical mapping existed played with the lab's: it keeps it, whatever the
    // program a new instance starts with.
    if (!tree.getChildWithProperty("id", engine::ids::mapping).isValid())
    {
        juce::ValueTree mapping("PARAM");
        mapping.setProperty("id", engine::ids::mapping, nullptr);
        mapping.setProperty("value", static_cast<int>(player::Mapping::Lab), nullptr);
        tree.appendChild(mapping, nullptr);
    }
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
    if (static_cast<int>(tree.getProperty("stateVersion", 0)) > kStateVersion)
        std::cerr << "rosin: state from a newer version; reading what is known\n";
    migrateState(tree);
    const int program = engine::findProgram(programs_, tree.getProperty("program").toString().toStdString());
    std::string problem;
    std::optional<ProgramFile> file = restoreProgramFile(tree, problem);
    if (!problem.empty())
        std::cerr << "rosin: state: " << problem << "; playing program "
                  << programs_[static_cast<std::size_t>(program)].name << "\n";
    {
        std::lock_guard<std::mutex> lock(builderMutex_);
        currentProgram_ = program;
        extras_.preset = file ? file->preset : programs_[static_cast<std::size_t>(program)].preset;
        programFileStatus_ =
            file ? "program " + juce::String(file->preset.name) + ", the copy saved from " + file->path
                 : juce::String(problem);
        programFile_ = std::move(file);
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
