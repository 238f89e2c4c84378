// Names a rule file may not give to element types, dynamic children or parameters, because the
// generated C++ (or C++ itself) already uses them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace acanthus {

// Why `name` cannot be declared, or nothing when it can.
std::optional<std::string> reserved_name_problem(std::string_view name);

// Levenshtein distance, for "did you mean" hints.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace acanthus
