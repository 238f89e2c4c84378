// libFuzzer target for the growth library's readers: any input is either a reference that grows
// (a few dozen motifs in a small panel) or an InputError.
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace growth = acanthus::growth;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    static const acanthus::Region panel = acanthus::Region::from_spec("rect:200,120");
    try {
        growth::Reference reference = growth::Reference::from_json_string(text, "fuzz.json");
        growth::Options options;
        options.max_elements = 40;
        for (growth::Mode mode : {growth::Mode::none, growth::Mode::rotation}) {
            options.mode = mode;
            (void)growth::synthesize(reference, panel, options, {}, 1);
        }
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
