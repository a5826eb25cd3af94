#include "WavEssentialsStream.h"

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
    juce::MemoryOutputStream chunks; // after "WAVE", up to the first sample byte
    bool ok = !chunk.rf64 || copyChunk(in, chunk.ds64ChunkOffset, chunk.ds64ChunkBytes, chunks);
    ok = ok && copyChunk(in, chunk.formatChunkOffset, chunk.formatChunkBytes, chunks);
    ok =
        ok && copyRange(in, chunk.offset - 8, 8, chunks); // the data chunk's own header, its length unchanged
    if (!ok)
        return nullptr;
    juce::MemoryOutputStream head;
    head.write(chunk.rf64 ? "RF64" : "RIFF", 4);
    // RF64 keeps its sizes in ds64; a RIFF size cannot say more than 32 bits hold.
    const juce::uint64 riffBytes = 4 + chunks.getDataSize() + chunk.presentBytes;
    head.writeInt(chunk.rf64 ? -1 : static_cast<int>(std::min<juce::uint64>(riffBytes, 0xffffffffu)));
    head.write("WAVE", 4);
    head << chunks.getMemoryBlock();
    auto data = std::make_unique<juce::FileInputStream>(file);
    if (!data->openedOk())
        return nullptr;
    auto tail =
        std::make_unique<juce::SubregionStream>(data.release(), static_cast<juce::int64>(chunk.offset),
                                                static_cast<juce::int64>(chunk.presentBytes), true);
    return std::make_unique<HeadThenTailStream>(head.getMemoryBlock(), std::move(tail));
}

} // namespace rosin::discovery
