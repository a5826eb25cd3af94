// rosin-editor-screenshot: opens Rosin's editor on a processor that is bowing a double stop, so the readouts
// and the Schelleng diagram are live, and writes a PNG of it (default: Resources/screenshots/editor.png).
//   rosin-editor-screenshot [OUT.png [WIDTHxHEIGHT]]   (the size checks the layout when resized)
// Run it under a display (`xvfb-run -a`): the editor is then put in a real desktop window first, and the
// program fails if that window has no peer. Without a display it still renders the snapshot off-screen.
#include <iostream>
#include <memory>

#include <juce_audio_processors/juce_audio_processors.h>
#include <juce_gui_basics/juce_gui_basics.h>

#include "instrument/plugin/RosinEditor.h"
#include "instrument/plugin/RosinProcessor.h"

namespace
{
constexpr double kSampleRate = 48000.0;
constexpr int kBlock = 256;

void render(rosin::plugin::RosinProcessor& p, juce::AudioBuffer<float>& buffer, juce::MidiBuffer& midi,
            int blocks)
{
    for (int b = 0; b < blocks; ++b)
    {
        p.processBlock(buffer, midi);
        midi.clear();
    }
}
} // namespace

// A JUCE application, so JUCE installs its X error handlers (it does so only for standalone apps): without a
// window manager, as under a bare Xvfb, some window-manager atoms do not exist and Xlib's default handler
// would exit on the first BadAtom.
class ScreenshotApp : public juce::JUCEApplication, private juce::Timer
{
  public:
    const juce::String getApplicationName() override { return "rosin-editor-screenshot"; }
    const juce::String getApplicationVersion() override { return "1"; }
    bool moreThanOneInstanceAllowed() override { return true; }

    void initialise(const juce::String&) override
    {
        const auto args = getCommandLineParameterArray();
        out_ = args.isEmpty() ? juce::File(ROSIN_SCREENSHOT_PATH)
                              : juce::File::getCurrentWorkingDirectory().getChildFile(args[0]);
        processor_ = std::make_unique<rosin::plugin::RosinProcessor>();
        processor_->setPlayConfigDetails(0, 2, kSampleRate, kBlock);
        processor_->prepareToPlay(kSampleRate, kBlock);

        // A double stop on the cello (D3 on string II, A3 on string I), bowed for a second so the contact
        // warms.
        midi_.addEvent(juce::MidiMessage::noteOn(1, 57, 0.8f), 0);
        midi_.addEvent(juce::MidiMessage::noteOn(1, 50, 0.8f), 1);
        render(*processor_, buffer_, midi_, static_cast<int>(1.0 * kSampleRate / kBlock));

        editor_.reset(processor_->createEditor());
        if (dynamic_cast<rosin::plugin::RosinEditor*>(editor_.get()) == nullptr)
            return fail("createEditor did not return a RosinEditor");
        haveDisplay_ = juce::Desktop::getInstance().getDisplays().getPrimaryDisplay() != nullptr;
        if (haveDisplay_)
        {
            editor_->addToDesktop(juce::ComponentPeer::windowHasTitleBar |
                                  juce::ComponentPeer::windowIsResizable);
            editor_->setVisible(true);
            if (editor_->getPeer() == nullptr)
                return fail("the editor window has no peer");
        }
        if (args.size() > 1)
        {
            const auto size = juce::StringArray::fromTokens(args[1], "x", "");
            if (size.size() == 2)
                editor_->setSize(size[0].getIntValue(), size[1].getIntValue());
        }
        startTimer(50); // let the window map and the message loop run before the snapshot
    }

    void shutdown() override
    {
        if (editor_ != nullptr && haveDisplay_)
            editor_->removeFromDesktop();
        editor_.reset();
        if (processor_ != nullptr)
            processor_->releaseResources();
        processor_.reset();
    }

    void systemRequestedQuit() override { quit(); }

  private:
    void fail(const juce::String& why)
    {
        std::cerr << "rosin-editor-screenshot: " << why << "\n";
        setApplicationReturnValue(1);
        quit();
    }

    void timerCallback() override
    {
        stopTimer();
        // A slow crescendo with CC1 while the readouts update at ~30 Hz: the point leaves a trail.
        auto& editor = dynamic_cast<rosin::plugin::RosinEditor&>(*editor_);
        const int blocksPerFrame = static_cast<int>(kSampleRate / 30.0 / kBlock);
        for (int frame = 0; frame < 24; ++frame)
        {
            midi_.addEvent(juce::MidiMessage::controllerEvent(1, 1, 64 + frame), 0);
            render(*processor_, buffer_, midi_, blocksPerFrame);
            editor.refreshReadouts();
        }

        const juce::Image image = editor.createComponentSnapshot(editor.getLocalBounds(), true, 1.0f);
        out_.getParentDirectory().createDirectory();
        out_.deleteFile();
        bool written = false;
        if (auto stream = out_.createOutputStream())
        {
            juce::PNGImageFormat png;
            written = png.writeImageToStream(image, *stream);
        }
        if (!written)
            return fail("could not write " + out_.getFullPathName());
        std::cout << "wrote " << out_.getFullPathName() << " (" << image.getWidth() << "x"
                  << image.getHeight() << (haveDisplay_ ? ", shown in a desktop window" : ", off-screen")
                  << ")\n";
        quit();
    }

    juce::File out_;
    std::unique_ptr<rosin::plugin::RosinProcessor> processor_;
    std::unique_ptr<juce::AudioProcessorEditor> editor_;
    juce::AudioBuffer<float> buffer_{2, kBlock};
    juce::MidiBuffer midi_;
    bool haveDisplay_ = false;
};

START_JUCE_APPLICATION(ScreenshotApp)
