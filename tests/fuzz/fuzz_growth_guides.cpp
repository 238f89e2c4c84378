// libFuzzer target for the growth library's guides reader (flow, boundary and spray strokes):
// guides that load are given to a fixed two-symbol reference grown in every mode, so the flow
// field, the boundary tests and the brushes see what the reader let through; anything else
// must be an InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "fuzz_growth_grow.hpp"

namespace {

// A jittered 6 x 6 two-symbol lattice: interior elements, rings of both symbols.
const acanthus::growth::Reference& reference() {
    static const acanthus::growth::Reference r = [] {
        std::vector<acanthus::growth::ReferenceElement> elements;
        for (int i = 0; i < 36; ++i) {
            acanthus::growth::ReferenceElement e;
            e.symbol.assign(1, i % 3 == 0 ? 'a' : 'b');
            e.position = {i % 6 * 10.0 + (i / 6 % 2) * 5.0 + (i * 7 % 5) * 0.3,
                          i / 6 * 8.7 + (i * 3 % 4) * 0.3};
            e.angle = i * 0.1;
            elements.push_back(e);
        }
        return acanthus::growth::Reference::from_elements(std::move(elements), {},
                                                          "fuzz-reference");
    }();
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        acanthus::growth::Options options;
        acanthus::growth::Guides::from_svg_string(text, "fuzz-guides.svg").add_to(options);
        fuzz_growth::grow(reference(), options);
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
