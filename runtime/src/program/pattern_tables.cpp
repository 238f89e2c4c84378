// make_pattern (<acanthus/pattern.hpp>): a Pattern from the constant tables of generated code.
#include <acanthus/pattern_tables.hpp>
#include <span>

namespace acanthus {

Pattern make_pattern(const PatternTables& t) {
    Pattern p;
    p.name = t.name;
    p.file = t.file;
    p.types.assign(t.types, t.types + t.type_count);
    p.seed = t.seed;
    p.rules.reserve(t.rule_count);
    for (const RuleEntry& r : std::span(t.rules, t.rule_count))
        p.rules.push_back({r.name, r.line, r.file, r.parent,
                           std::vector<const ElementType*>(r.children, r.children + r.child_count),
                           r.body});
    p.params.reserve(t.param_count);
    for (const ParamEntry& e : std::span(t.params, t.param_count))
        p.params.push_back(
            {e.name, e.type, e.default_text, e.line, e.assign, e.current, e.low, e.high});
    p.exhausted = t.exhausted;
    p.exhausted_line = t.exhausted_line;
    return p;
}

}  // namespace acanthus
