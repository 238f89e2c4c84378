// User field declarations of an %element: finds simple declarations without an initializer
// (they get `{}` so `new leaf` yields zeroed fields) and the fields of simple types the JSON
// element tree records.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace acanthus {

struct MemberField {
    std::string name;
    std::string type;  // normalized: "int", "unsigned int", "std::string", ...
};

struct MemberAnalysis {
    std::string text;  // the declarations with `{}` inserted; same line structure
    std::vector<MemberField>
        fields;  // simple fields of type int/long/unsigned/float/double/bool/std::string
};

MemberAnalysis analyze_members(std::string_view text);

}  // namespace acanthus
