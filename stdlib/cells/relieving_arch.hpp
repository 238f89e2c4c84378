// Relieving arches over the lintels of openings labelled `relieving` (relieving_arch.cpp).
#pragma once

#include <acanthus/stdlib/cells.hpp>

namespace acanthus::cells::detail {

// Whether edge `e` is labelled `relieving`.
bool relieving(const Edge& e);
// The narrowest opening a relieving arch is turned over: six courses, so that its rise (a
// sixth of its span) is at least a course.
double relieving_least_span(const Options& options);

}  // namespace acanthus::cells::detail
