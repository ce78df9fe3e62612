// libFuzzer target: see fuzz_entries.hpp for what obj_entry feeds to the product and what it checks.
#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    lancer::fuzz::obj_entry(data, size);
    return 0;
}
