#include "instrument/plugin/EngineSlot.h"

namespace rosin::plugin
{

EngineSlot::~EngineSlot()
{
    delete pending_.exchange(nullptr);
    delete retired_.exchange(nullptr);
    delete active_;
}

void EngineSlot::publish(std::unique_ptr<Engine> engine)
{
    delete pending_.exchange(engine.release(), std::memory_order_acq_rel);
}

void EngineSlot::collect()
{
    delete retired_.exchange(nullptr, std::memory_order_acq_rel);
}

void EngineSlot::installNow(std::unique_ptr<Engine> engine)
{
    delete pending_.exchange(nullptr);
    delete retired_.exchange(nullptr);
    delete active_;
    active_ = engine.release();
}

Engine* EngineSlot::acquire() noexcept
{
    if (pending_.load(std::memory_order_acquire) != nullptr &&
        retired_.load(std::memory_order_acquire) == nullptr)
    {
        if (Engine* next = pending_.exchange(nullptr, std::memory_order_acq_rel))
        {
            retired_.store(active_, std::memory_order_release);
            active_ = next;
        }
    }
    return active_;
}

} // namespace rosin::plugin
