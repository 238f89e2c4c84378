// libFuzzer target for the growth library's JSON reference reader: what loads is grown (a few
// dozen motifs in a small panel); anything else must be an InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_growth_grow.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        fuzz_growth::grow(acanthus::growth::Reference::from_json_string(text, "fuzz.json"), {});
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
