#pragma once
// A place for data derived from an object on first use, built once even when many threads ask
// at the same time (the CPU renderer intersects one surface from all cores). A copy of the
// slot starts empty, so a copied object that is then changed never sees stale data.
#include <memory>
#include <mutex>
#include <stdexcept>
#include <typeinfo>

namespace lancer::surface {

class LazySlot {
public:
    LazySlot() = default;
    LazySlot(const LazySlot&) {}
    LazySlot(LazySlot&&) noexcept {}
    LazySlot& operator=(const LazySlot&) {
        state_ = std::make_unique<State>();
        return *this;
    }
    LazySlot& operator=(LazySlot&&) noexcept {
        state_ = std::make_unique<State>();
        return *this;
    }

    // The value build() made on the first call (a failed build is retried by the next call).
    // One slot holds one type.
    template <class T, class Build>
    const T& get(Build&& build) const {
        std::call_once(state_->once, [&] {
            state_->value = std::make_shared<const T>(build());
            state_->type = &typeid(T);
        });
        if (*state_->type != typeid(T)) throw std::logic_error("LazySlot: asked for a different type");
        return *static_cast<const T*>(state_->value.get());
    }

private:
    struct State {
        std::once_flag once;
        std::shared_ptr<const void> value;
        const std::type_info* type = nullptr;
    };
    std::unique_ptr<State> state_ = std::make_unique<State>();
};

}  // namespace lancer::surface
