#include "image/decode_budget.hpp"

#include <cstdlib>
#include <cstdint>

namespace lancer {
namespace {

// Each block carries its size in front of it, so that free and realloc can count it back.
constexpr std::size_t kHeader = 16;  // keeps the block 16-byte aligned, as malloc's

struct Budget {
    std::size_t limit = 0;
    std::size_t used = 0;
    bool exceeded = false;
};

thread_local Budget* g_budget = nullptr;

std::size_t& size_of(void* block) { return *reinterpret_cast<std::size_t*>(static_cast<char*>(block) - kHeader); }

bool admit(std::size_t add, std::size_t remove) {
    if (!g_budget) return true;
    std::size_t after = g_budget->used > remove ? g_budget->used - remove : 0;  // blocks from before the budget
    if (add > g_budget->limit || after > g_budget->limit - add) {
        g_budget->exceeded = true;
        return false;
    }
    g_budget->used = after + add;
    return true;
}

}  // namespace

DecodeBudget::DecodeBudget(std::size_t bytes) { g_budget = new Budget{bytes}; }

DecodeBudget::~DecodeBudget() {
    delete g_budget;
    g_budget = nullptr;
}

bool DecodeBudget::exceeded() const { return g_budget && g_budget->exceeded; }

void* budget_malloc(std::size_t bytes) {
    if (bytes > SIZE_MAX - kHeader || !admit(bytes, 0)) return nullptr;
    void* raw = std::malloc(bytes + kHeader);
    if (!raw) {
        admit(0, bytes);
        return nullptr;
    }
    void* block = static_cast<char*>(raw) + kHeader;
    size_of(block) = bytes;
    return block;
}

void* budget_realloc(void* block, std::size_t bytes) {
    if (!block) return budget_malloc(bytes);
    const std::size_t old = size_of(block);
    if (bytes > SIZE_MAX - kHeader || !admit(bytes, old)) return nullptr;
    void* raw = std::realloc(static_cast<char*>(block) - kHeader, bytes + kHeader);
    if (!raw) {
        admit(old, bytes);
        return nullptr;
    }
    void* moved = static_cast<char*>(raw) + kHeader;
    size_of(moved) = bytes;
    return moved;
}

void budget_free(void* block) {
    if (!block) return;
    admit(0, size_of(block));
    std::free(static_cast<char*>(block) - kHeader);
}

}  // namespace lancer
