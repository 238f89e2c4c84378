// libFuzzer target for the growth library's readers: an input starting with '<' is read both as
// an SVG reference and as guides, anything else as a JSON reference. What loads is grown (a few
// dozen motifs in a small panel, with the guides' tools); anything else must be an InputError.
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace {

namespace growth = acanthus::growth;

void grow(const growth::Reference& reference, const growth::Options& base) {
    static const acanthus::Region panel = acanthus::Region::from_spec("rect:200,120");
    growth::Options options = base;
    options.max_elements = 40;
    for (growth::Mode mode : {growth::Mode::none, growth::Mode::rotation, growth::Mode::flow}) {
        if (mode == growth::Mode::flow && options.flow_strokes.empty()) continue;
        options.mode = mode;
        try {
            (void)growth::synthesize(reference, panel, options, {}, 1);
        } catch (const acanthus::InputError&) {  // strokes beyond the range, no start inside
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        if (!text.empty() && text.front() == '<') {
            growth::Options options;
            std::optional<growth::Reference> reference;
            try {
                growth::Guides::from_svg_string(text, "fuzz-guides.svg").add_to(options);
            } catch (const acanthus::InputError&) {
            }
            reference.emplace(growth::Reference::from_svg_string(text, "fuzz.svg"));
            grow(*reference, options);
        } else {
            grow(growth::Reference::from_json_string(text, "fuzz.json"), {});
        }
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
