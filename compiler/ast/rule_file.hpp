// One parsed rule file: its sections in file order.
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

#include "draw_decl.hpp"
#include "element_decl.hpp"
#include "exhausted_decl.hpp"
#include "import_decl.hpp"
#include "param_decl.hpp"
#include "rule_decl.hpp"
#include "source_decl.hpp"

namespace acanthus::ast {

using Section =
    std::variant<ElementDecl, SourceDecl, RuleDecl, DrawDecl, ParamDecl, ImportDecl, ExhaustedDecl>;

struct RuleFile {
    std::uint32_t file = 0;  // index into SourceFiles
    std::vector<Section> sections;
};

}  // namespace acanthus::ast
