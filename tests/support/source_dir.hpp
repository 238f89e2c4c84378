// The checkout's root for the tests and benches, which read examples, rules and references from it.
// It is compiled into one object (source_dir.cpp) and not into every test, so that the tests'
// objects do not depend on where the checkout is and ccache serves them across clones. A global
// name: tests that use namespace acanthus also use gtest's ::testing.
#pragma once

const char* acanthus_test_source_dir();

#define ACANTHUS_SOURCE_DIR (::acanthus_test_source_dir())
