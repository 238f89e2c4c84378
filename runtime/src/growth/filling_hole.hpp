// Whether the growth engine offers a hole of a symmetric ornament to the running body.
#pragma once

#include <acanthus/environment.hpp>

namespace acanthus::detail {

// True while `env` is the growth engine's and it offers a hole left at a special point of a
// symmetry group (a rotation centre, a mirror) when growth ended, env.region() then being that
// hole: a library that sizes its elements by its options may try smaller ones there, since by a
// rotation centre with mirrors an element not symmetric fits only in a narrow wedge.
bool filling_hole(const Environment& env);

}  // namespace acanthus::detail
