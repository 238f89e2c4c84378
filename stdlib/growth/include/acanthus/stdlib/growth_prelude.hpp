// For `acanthus preview`'s precompiled prelude, included after <acanthus/stdlib/growth.hpp>
// when a rule file's code includes that: the standard library's members the growth library's
// rule code uses (its options, guides, motifs and maps of symbols), instantiated once with the
// prelude instead of at every save. Never called.
#pragma once

#include <acanthus/stdlib/growth.hpp>

namespace acanthus::growth::prelude_detail {

inline void instantiate() {
    Options options, copy(options);
    copy = options;
    options.priority["a"] = 1;
    (void)options.priority.count("a");
    (void)options.priority.find("a");
    options.spray_strokes.push_back({});
    options.flow_strokes.push_back({});
    Guides guides, other(guides);
    other = guides;
    SynthesisResult result, again(result);
    again = result;
    result.motifs.push_back(Motif{});
    result.motifs.emplace_back();
    for (const Motif& m : result.motifs) (void)m;
    Fidelity fidelity, same(fidelity);
    same = fidelity;
    fidelity.symbol_mix["a"] = 0.0;
    (void)fidelity.symbol_mix.find("a");
    for (const auto& entry : fidelity.symbol_mix) (void)entry;
}

}  // namespace acanthus::growth::prelude_detail
