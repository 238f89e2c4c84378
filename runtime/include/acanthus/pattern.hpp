// The compiled form of a rule file: element types, rules, parameters, %exhausted.
#pragma once

#include <acanthus/element.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus {

class RuleCall;

enum Result { FAILURE = 0, SUCCESS = 1 };
enum Flow { STOP = 0, CONTINUE = 1 };

struct RuleInfo {
    std::string name;  // "flower --> stem flower"
    int line = 0;      // line of %rule in `file`
    std::string file;  // rule file the rule came from (imports keep their own)
    const ElementType* parent = nullptr;
    std::vector<const ElementType*> children;  // static children, in order
    Result (*body)(RuleCall&) = nullptr;
};

struct ParamInfo {
    std::string name;
    std::string type;          // "int", "double", "bool", "std::string"
    std::string default_text;  // as written in the rule file
    int line = 0;
    // Parses `text` into the parameter; false with `error` set on a bad value.
    bool (*assign)(std::string_view text, std::string& error) = nullptr;
    std::string (*current)() = nullptr;
    // `in [LO, HI]` as written, numeric parameters only; both empty when none was declared.
    std::string low;
    std::string high;
};

struct Pattern {
    std::string name;  // rule file stem, e.g. "flowers"
    std::string file;  // rule file path as given to the compiler
    std::vector<const ElementType*> types;
    const ElementType* seed = nullptr;
    std::vector<RuleInfo> rules;  // file order, imports where %import stands
    std::vector<ParamInfo> params;
    Flow (*exhausted)() = nullptr;  // null means STOP
    int exhausted_line = 0;
};

}  // namespace acanthus
