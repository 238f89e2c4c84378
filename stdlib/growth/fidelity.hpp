// The fidelity report (Options-independent): the grown motifs measured against the reference as
// an author would look at them, so a run says at once when a reference grows badly.
#pragma once

#include <acanthus/stdlib/growth.hpp>

#include "panel.hpp"
#include "reference.hpp"

namespace acanthus::growth::detail {

// `spacing`: the reference's NN median; `largest_hole`: in drawing units.
Fidelity measure_fidelity(const ReferenceData& reference, const std::vector<Motif>& motifs,
                          const Panel& panel, double spacing, double largest_hole);

}  // namespace acanthus::growth::detail
