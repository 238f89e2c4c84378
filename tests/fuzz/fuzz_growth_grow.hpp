// What the growth fuzz targets do with an input that loads: grow a few dozen motifs from it in a
// small panel, in every mode its options allow. An InputError there (strokes beyond the range,
// no start inside) is an answer, not a failure.
#pragma once
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>

namespace fuzz_growth {

inline void grow(const acanthus::growth::Reference& reference,
                 const acanthus::growth::Options& base) {
    namespace growth = acanthus::growth;
    static const acanthus::Region panel = acanthus::Region::from_spec("rect:200,120");
    growth::Options options = base;
    options.max_elements = 40;
    for (growth::Mode mode : {growth::Mode::none, growth::Mode::rotation, growth::Mode::flow}) {
        if (mode == growth::Mode::flow && options.flow_strokes.empty()) continue;
        options.mode = mode;
        try {
            (void)growth::synthesize(reference, panel, options, {}, 1);
        } catch (const acanthus::InputError&) {
        }
    }
}

}  // namespace fuzz_growth
