// A partial picture from inside one long rule body: a library that places hundreds of shapes in
// one call (dartfill's fill) reports them as it goes, so that a viewer (acanthus preview, through
// the program's --partial) sees them come before the body returns.
#pragma once

#include <functional>
#include <vector>

namespace acanthus {

class Element;

// Makes elements for what the body placed so far (new, never freed: it runs only in the copy of
// the program that draws the picture, which ends after it).
using PartialElements = std::function<void(std::vector<const Element*>& out)>;

// `placed`: how many the running body placed so far; a picture is due only when it grew. When
// the program draws --partial pictures and one is due, the copy drawing it calls `extra` and
// draws its elements after those already placed. Otherwise it returns at once (a clock read).
void report_partial(long placed, const PartialElements& extra);

namespace detail {

// Set by the program while it grows with --partial; null (the default) ignores reports.
using PartialHandler = void (*)(void* context, long placed, const PartialElements& extra);
void set_partial_handler(PartialHandler handler, void* context) noexcept;

}  // namespace detail

}  // namespace acanthus
