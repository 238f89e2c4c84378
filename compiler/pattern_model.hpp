// The checked meaning of a rule program: element types with their proxies, rules with their
// resolved types, parameters, %draw and %exhausted. What the code generator reads.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "param_type.hpp"
#include "proxy_kinds.hpp"
#include "rule_program.hpp"

namespace acanthus {

struct ElementModel {
    const ast::ElementDecl* decl = nullptr;
    std::uint32_t file = 0;
    std::string name;
    std::vector<ProxyKindInfo> proxies;
    const ast::DrawDecl* draw = nullptr;
};

struct RuleModel {
    const ast::RuleDecl* decl = nullptr;
    std::uint32_t file = 0;
    int index = 0;  // rule order over all imports
    const ElementModel* parent = nullptr;
    std::vector<const ElementModel*> children;
    std::map<std::string, const ElementModel*> vars;  // `* var type`
    std::string name;                                 // "flower --> stem flower"
};

struct ParamModel {
    const ast::ParamDecl* decl = nullptr;
    std::uint32_t file = 0;
    ParamType type;
};

struct DrawModel {
    const ast::DrawDecl* decl = nullptr;
    std::uint32_t file = 0;
    const ElementModel* element = nullptr;
};

struct PatternModel {
    RuleProgram program;
    // Owned by pointer so references stay valid while the model is built.
    std::vector<std::unique_ptr<ElementModel>> elements;  // declaration order
    std::vector<RuleModel> rules;
    std::vector<ParamModel> params;
    std::vector<DrawModel> draws;
    const ast::ExhaustedDecl* exhausted = nullptr;
    std::uint32_t exhausted_file = 0;
    const ElementModel* seed = nullptr;

    std::map<std::string, const ElementModel*> by_name;  // the same elements, for lookup

    const ElementModel* find_element(const std::string& name) const;
};

}  // namespace acanthus
