#pragma once
// A T kept on the heap, with a value's semantics (copies are deep, there is always a value): a
// pointer's size in its owner. For the large members of a type most of a million values lack
// (an implicit surface in the Shape variant, where a sphere needs a fifth of its size).
#include <memory>
#include <utility>

namespace lancer {

template <class T>
class HeapValue {
public:
    HeapValue() : value_(std::make_unique<T>()) {}
    HeapValue(T value) : value_(std::make_unique<T>(std::move(value))) {}
    HeapValue(const HeapValue& other) : value_(std::make_unique<T>(*other)) {}
    HeapValue(HeapValue&&) noexcept = default;  // leaves `other` empty: only assignment and destruction are valid on it
    HeapValue& operator=(const HeapValue& other) {
        if (this != &other) value_ = std::make_unique<T>(*other);
        return *this;
    }
    HeapValue& operator=(HeapValue&&) noexcept = default;

    T& operator*() { return *value_; }
    const T& operator*() const { return *value_; }
    T* operator->() { return value_.get(); }
    const T* operator->() const { return value_.get(); }

private:
    std::unique_ptr<T> value_;
};

}  // namespace lancer
