// The checkout's root for the tests and benches, which read examples, rules and references from it.
// It is compiled into one object (source_dir.cpp) and not into every test, so that the tests'
// objects do not depend on where the checkout is and ccache serves them across clones.
#pragma once

namespace acanthus::testing {
const char* source_dir();
}

#define ACANTHUS_SOURCE_DIR (::acanthus::testing::source_dir())
