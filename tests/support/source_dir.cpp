#include "source_dir.hpp"

const char* acanthus_test_source_dir() { return ACANTHUS_CHECKOUT_DIR; }
