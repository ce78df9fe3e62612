#pragma once
// A string that most of a million values leave empty (an object's name): a pointer's size, not
// std::string's 32 bytes, where it is empty. Reads as a const std::string&.
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace lancer {

class RareString {
public:
    RareString() = default;
    RareString(std::string text) : text_(text.empty() ? nullptr : std::make_unique<const std::string>(std::move(text))) {}
    RareString(const char* text) : RareString(std::string(text)) {}
    RareString(const RareString& other) : RareString(other.str()) {}
    RareString(RareString&&) noexcept = default;
    RareString& operator=(const RareString& other) {
        if (this != &other) *this = RareString(other);
        return *this;
    }
    RareString& operator=(RareString&&) noexcept = default;

    const std::string& str() const { return text_ ? *text_ : no_text(); }
    operator const std::string&() const { return str(); }
    bool empty() const { return text_ == nullptr; }
    friend bool operator==(const RareString& a, std::string_view b) { return a.str() == b; }
    friend bool operator==(const RareString& a, const char* b) { return a.str() == b; }
    friend bool operator==(const RareString& a, const RareString& b) { return a.str() == b.str(); }

private:
    static const std::string& no_text() {
        static const std::string none;
        return none;
    }
    std::unique_ptr<const std::string> text_;
};

}  // namespace lancer
