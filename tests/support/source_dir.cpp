#include "source_dir.hpp"

namespace acanthus::testing {
const char* source_dir() { return ACANTHUS_CHECKOUT_DIR; }
}  // namespace acanthus::testing
