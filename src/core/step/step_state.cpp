// Ownership of the step state behind the World facade (world.h StepStateBox, step_state.h).
#include "step_state.h"

#include "implicit_euler.h"

namespace clothtear {

StepStateBox::StepStateBox() : state_(std::make_unique<StepState>()) {}
StepStateBox::~StepStateBox() = default;
StepStateBox::StepStateBox(const StepStateBox& other) : state_(std::make_unique<StepState>(*other.state_)) {}
StepStateBox& StepStateBox::operator=(const StepStateBox& other) {
    if (this != &other) *state_ = *other.state_;
    return *this;
}
// A moved-from box gets a fresh state: a World stays usable after being moved from.
StepStateBox::StepStateBox(StepStateBox&& other) noexcept : state_(std::move(other.state_)) {
    other.state_ = std::make_unique<StepState>();
}
StepStateBox& StepStateBox::operator=(StepStateBox&& other) noexcept {
    std::swap(state_, other.state_);
    return *this;
}

ImplicitCacheSlot::ImplicitCacheSlot() = default;
ImplicitCacheSlot::~ImplicitCacheSlot() = default;
// The matrix is rebuilt on the copy's first implicit step (an empty slot is stale).
ImplicitCacheSlot::ImplicitCacheSlot(const ImplicitCacheSlot&) {}
ImplicitCacheSlot& ImplicitCacheSlot::operator=(const ImplicitCacheSlot& other) {
    if (this != &other) {
        cache.reset();
        stamp = CacheStamp{};
    }
    return *this;
}

} // namespace clothtear
