#include "lab/discovery/io/WavEssentialsStream.h"

#include <algorithm>
#include <cstring>

namespace rosin::discovery
{

namespace
{
/// `head` (in memory) followed by `tail`, as one stream.
class HeadThenTailStream final : public juce::InputStream
{
  public:
    HeadThenTailStream(juce::MemoryBlock head, std::unique_ptr<juce::InputStream> tail)
        : head_(std::move(head)), tail_(std::move(tail))
    {
    }

    juce::int64 getTotalLength() override { return headBytes() + tail_->getTotalLength(); }
    bool isExhausted() override { return position_ >= getTotalLength(); }
    juce::int64 getPosition() override { return position_; }

    bool setPosition(juce::int64 position) override
    {
        position_ = std::clamp<juce::int64>(position, 0, getTotalLength());
        return position_ < headBytes() || tail_->setPosition(position_ - headBytes());
    }

    int read(void* destination, int maxBytes) override
    {
        auto* out = static_cast<char*>(destination);
        int done = 0;
        if (position_ < headBytes() && maxBytes > 0)
        {
            const auto n = static_cast<int>(std::min<juce::int64>(maxBytes, headBytes() - position_));
            std::memcpy(out, static_cast<const char*>(head_.getData()) + position_, static_cast<size_t>(n));
            done = n;
            position_ += n;
            if (position_ == headBytes())
                tail_->setPosition(0);
        }
        if (done < maxBytes && position_ >= headBytes())
        {
            const int n = tail_->read(out + done, maxBytes - done);
            done += std::max(n, 0);
            position_ += std::max(n, 0);
        }
        return done;
    }

  private:
    juce::int64 headBytes() const { return static_cast<juce::int64>(head_.getSize()); }

    juce::MemoryBlock head_;
    std::unique_ptr<juce::InputStream> tail_;
    juce::int64 position_ = 0;
};

bool copyRange(juce::FileInputStream& in, juce::uint64 offset, juce::uint64 bytes,
               juce::MemoryOutputStream& out)
{
    return in.setPosition(static_cast<juce::int64>(offset)) &&
           out.writeFromInputStream(in, static_cast<juce::int64>(bytes)) == static_cast<juce::int64>(bytes);
}
// A whole chunk, header included, and the pad byte that keeps the next one at an even offset (whatever the
// file held there: readers skip it).
bool copyChunk(juce::FileInputStream& in, juce::uint64 offset, juce::uint64 bytes,
               juce::MemoryOutputStream& out)
{
    const bool ok = copyRange(in, offset, bytes, out);
    if (bytes & 1)
        out.writeByte(0);
    return ok;
}
} // namespace

std::unique_ptr<juce::InputStream> openWavEssentials(const juce::File& file, const WavDataChunk& chunk)
{
    juce::FileInputStream in(file);
    if (!in.openedOk())
        return nullptr;
    juce::MemoryOutputStream format; // the first fmt chunk as the file has it, and its pad byte
    if (!copyChunk(in, chunk.formatChunkOffset, chunk.formatChunkBytes, format))
        return nullptr;
    // The sizes are written anew from what findWavDataChunk decided, so JUCE's reader cannot see the data end
    // elsewhere (fuzzing found two ways: a ds64 data size it reads as negative, and one the data chunk's own
    // size contradicts) and go on to read samples as chunks. RF64: a ds64 chunk of 28 bytes.
    const juce::uint64 ds64Bytes = chunk.rf64 ? 8 + 28 : 0;
    const juce::uint64 riffBytes = 4 + ds64Bytes + format.getDataSize() + 8 + chunk.declaredBytes;
    juce::MemoryOutputStream head;
    head.write(chunk.rf64 ? "RF64" : "RIFF", 4);
    head.writeInt(chunk.rf64 ? -1 : static_cast<int>(std::min<juce::uint64>(riffBytes, 0xffffffffu)));
    head.write("WAVE", 4);
    if (chunk.rf64)
    {
        head.write("ds64", 4);
        head.writeInt(28);
        head.writeInt64(static_cast<juce::int64>(riffBytes));
        head.writeInt64(static_cast<juce::int64>(chunk.declaredBytes));
        head.writeInt64(0); // sample count: unused by readers that have the data size
        head.writeInt(0);   // no table
    }
    head << format.getMemoryBlock();
    head.write("data", 4);
    head.writeInt(chunk.rf64 ? -1 : static_cast<int>(chunk.declaredBytes)); // RIFF: it came from 32 bits
    auto data = std::make_unique<juce::FileInputStream>(file);
    if (!data->openedOk())
        return nullptr;
    auto tail =
        std::make_unique<juce::SubregionStream>(data.release(), static_cast<juce::int64>(chunk.offset),
                                                static_cast<juce::int64>(chunk.presentBytes), true);
    return std::make_unique<HeadThenTailStream>(head.getMemoryBlock(), std::move(tail));
}

} // namespace rosin::discovery
