#include "semantic_checker.hpp"

#include <set>

#include "reserved_names.hpp"

namespace acanthus {

const ElementModel* PatternModel::find_element(const std::string& name) const {
    auto it = by_name.find(name);
    return it == by_name.end() ? nullptr : it->second;
}

namespace {

using Target = ast::DollarToken::Target;

std::string quoted(std::string_view s) { return std::string("'").append(s).append("'"); }

std::string proxies(std::size_t n) { return std::to_string(n) + (n == 1 ? " proxy" : " proxies"); }

std::string token_text(const SourceFiles& files, const ast::DollarToken& d) {
    const std::string& text = files[d.where.begin.file].text();
    return text.substr(d.where.begin.offset, d.where.end.offset - d.where.begin.offset);
}

SourceRange span(const SourceRange& a, const SourceRange& b) { return SourceRange{a.begin, b.end}; }

class Checker {
  public:
    Checker(const RuleProgram& program, const SourceFiles& files, Diagnostics& diagnostics)
        : files_(files), diagnostics_(diagnostics) {
        model_.program = program;
    }

    PatternModel run() {
        for (const SectionRef& ref : model_.program.sections) {
            if (const auto* e = std::get_if<ast::ElementDecl>(ref.section)) element(*e, ref.file);
        }
        check_seed();
        int rule_index = 0;
        for (const SectionRef& ref : model_.program.sections) {
            const ast::Section& s = *ref.section;
            if (const auto* r = std::get_if<ast::RuleDecl>(&s)) rule(*r, ref.file, rule_index++);
            if (const auto* d = std::get_if<ast::DrawDecl>(&s)) draw(*d, ref.file);
            if (const auto* p = std::get_if<ast::ParamDecl>(&s)) param(*p, ref.file);
            if (const auto* x = std::get_if<ast::SourceDecl>(&s)) no_dollars(x->code, "%source");
            if (const auto* x = std::get_if<ast::ExhaustedDecl>(&s)) exhausted(*x, ref.file);
        }
        return std::move(model_);
    }

  private:
    // A name in the global namespace of the generated program: element types and parameters.
    bool declare_global(const ast::Name& name, std::string_view what) {
        if (auto problem = reserved_name_problem(name.text)) {
            diagnostics_.error(name.where, "cannot use " + quoted(name.text) + " as " +
                                               std::string(what) + ": " + *problem);
            return false;
        }
        auto [it, fresh] =
            globals_.emplace(name.text, std::make_pair(name.where, std::string(what)));
        if (!fresh) {
            const auto& [where, first_what] = it->second;
            std::string article = first_what == "element type" ? "an " : "a ";
            std::string message =
                first_what == what
                    ? "duplicate " + std::string(what) + " " + quoted(name.text)
                    : quoted(name.text) + " is already declared as " + article + first_what;
            diagnostics_.error(name.where, message,
                               {{where, quoted(name.text) + " first declared here"}});
            return false;
        }
        return true;
    }

    void element(const ast::ElementDecl& decl, std::uint32_t file) {
        no_dollars(decl.members, "%element");
        if (decl.header.empty()) {
            diagnostics_.error(decl.keyword,
                               "'%element' needs a header: a type name followed by one or more "
                               "proxy kinds, such as 'dot circle'");
            return;
        }
        const ast::Name& name = decl.header.front();
        if (decl.header.size() == 1) {
            diagnostics_.error(name.where, "element type " + quoted(name.text) +
                                               " needs at least one proxy kind (" +
                                               std::string(proxy_kind_list()) + ")");
        }
        auto model = std::make_unique<ElementModel>();
        model->decl = &decl;
        model->file = file;
        model->name = name.text;
        bool complete = decl.header.size() > 1;
        for (std::size_t i = 1; i < decl.header.size(); ++i) {
            const ast::Name& kind = decl.header[i];
            if (auto info = find_proxy_kind(kind.text)) {
                model->proxies.push_back(*info);
                continue;
            }
            complete = false;
            std::string message = "unknown proxy kind " + quoted(kind.text);
            std::string best;
            for (std::string_view k :
                 {"point", "circle", "arc", "linesegment", "bezier", "polygon"}) {
                if (edit_distance(kind.text, k) <= 2 && best.empty()) best = k;
            }
            if (!best.empty()) message += "; did you mean " + quoted(best) + "?";
            message += " (kinds: " + std::string(proxy_kind_list()) + ")";
            diagnostics_.error(kind.where, message);
        }
        if (!declare_global(name, "element type")) return;
        if (!complete) incomplete_.insert(model.get());
        model_.by_name.emplace(model->name, model.get());
        model_.elements.push_back(std::move(model));
    }

    void check_seed() {
        const ElementModel* seed = model_.find_element("seed");
        if (!seed) {
            bool declared = globals_.count("seed") > 0;  // declared, but malformed
            if (!declared) {
                diagnostics_.file_error(model_.program.main_file,
                                        "no element type 'seed': every rule file declares "
                                        "'seed' with one 'point' proxy (%element seed point)");
            }
            return;
        }
        model_.seed = seed;
        bool ok = seed->decl->header.size() == 2 && seed->proxies.size() == 1 &&
                  seed->proxies[0].name == "point";
        if (!ok && !incomplete_.count(seed)) {
            std::string kinds;
            for (std::size_t i = 1; i < seed->decl->header.size(); ++i) {
                kinds += (i > 1 ? " " : "") + seed->decl->header[i].text;
            }
            diagnostics_.error(seed->decl->header.front().where,
                               "element type 'seed' must have exactly one proxy, a 'point' "
                               "(declared: '" +
                                   kinds + "')");
        }
    }

    const ElementModel* lookup(const ast::Name& name) {
        if (const ElementModel* e = model_.find_element(name.text)) return e;
        if (globals_.count(name.text) && globals_.at(name.text).second == "element type") {
            return nullptr;  // declared but invalid: already reported
        }
        std::string message = "unknown element type " + quoted(name.text);
        const ElementModel* best = nullptr;
        std::size_t best_distance = 3;
        // Suggestions cost a distance per declared type; bound the work on huge inputs.
        if (suggestion_budget_ > model_.elements.size()) {
            suggestion_budget_ -= model_.elements.size();
            for (const auto& e : model_.elements) {
                std::size_t d = edit_distance(name.text.substr(0, 64), e->name.substr(0, 64));
                if (d < best_distance) best = e.get(), best_distance = d;
            }
        }
        if (best) message += "; did you mean " + quoted(best->name) + "?";
        diagnostics_.error(name.where, message);
        return nullptr;
    }

    // Checks (k) of a proxy token against `type`.
    void check_proxy_index(const ast::DollarToken& d, const ElementModel* type) {
        if (!d.explicit_proxy) return;
        if (d.proxy < 0) {
            diagnostics_.error(d.where,
                               "proxy index in " + quoted(token_text(files_, d)) + " is too large");
            return;
        }
        if (!type || incomplete_.count(type)) return;
        if (static_cast<std::size_t>(d.proxy) >= type->proxies.size()) {
            diagnostics_.error(d.where, quoted(token_text(files_, d)) + " refers to proxy " +
                                            std::to_string(d.proxy) + ", but " +
                                            quoted(type->name) + " has " +
                                            proxies(type->proxies.size()) + " (numbered from 0)");
        }
    }

    void rule(const ast::RuleDecl& decl, std::uint32_t file, int index) {
        RuleModel r;
        r.decl = &decl;
        r.file = file;
        r.index = index;
        r.parent = lookup(decl.parent);
        r.name = decl.parent.text + " -->";
        for (const ast::Name& child : decl.children) {
            r.name += " " + child.text;
            r.children.push_back(lookup(child));
        }
        std::map<std::string, SourceRange> var_where;
        for (const ast::DynamicChildDecl& dyn : decl.dynamics) {
            const ElementModel* type = lookup(dyn.type);
            if (dyn.var.text == "goal") {
                diagnostics_.error(
                    dyn.var.where,
                    "'goal' cannot name a dynamic child: '$goal' is the empty circle");
                continue;
            }
            if (auto problem = reserved_name_problem(dyn.var.text)) {
                diagnostics_.error(dyn.var.where, "cannot use " + quoted(dyn.var.text) +
                                                      " as a dynamic child: " + *problem);
                continue;
            }
            auto [it, fresh] = var_where.emplace(dyn.var.text, dyn.var.where);
            if (!fresh) {
                diagnostics_.error(dyn.var.where, "duplicate dynamic child " + quoted(dyn.var.text),
                                   {{it->second, quoted(dyn.var.text) + " first declared here"}});
                continue;
            }
            r.vars[dyn.var.text] = type;
        }
        if (!decl.body.present && decl.body.terminated) {
            diagnostics_.error(decl.keyword, "rule " + quoted(r.name) +
                                                 " has no body: expected '{' after the preamble");
        }
        for (const ast::DollarToken& d : decl.body.dollars) {
            switch (d.target) {
                case Target::bad:
                    diagnostics_.error(d.where, d.problem);
                    break;
                case Target::goal:
                    break;
                case Target::parent:
                    check_proxy_index(d, r.parent);
                    break;
                case Target::child: {
                    std::size_t n = decl.children.size();
                    if (d.child < 0 || static_cast<std::size_t>(d.child) >= n) {
                        std::string has =
                            n == 0 ? std::string("has no static children")
                            : n == 1
                                ? std::string("has 1 static child (numbered from 0)")
                                : "has " + std::to_string(n) + " static children (numbered from 0)";
                        diagnostics_.error(d.where, quoted(token_text(files_, d)) +
                                                        " refers to static child " +
                                                        (d.child < 0 ? std::string("beyond range")
                                                                     : std::to_string(d.child)) +
                                                        ", but rule " + quoted(r.name) + " " + has);
                        break;
                    }
                    check_proxy_index(d, r.children[static_cast<std::size_t>(d.child)]);
                    break;
                }
                case Target::var: {
                    if (!var_where.count(d.var)) {
                        diagnostics_.error(d.where, quoted(token_text(files_, d)) + " uses " +
                                                        quoted(d.var) +
                                                        ", which is not declared as a dynamic "
                                                        "child; add '* " +
                                                        d.var + " TYPE' to the rule preamble");
                        break;
                    }
                    auto it = r.vars.find(d.var);
                    check_proxy_index(d, it == r.vars.end() ? nullptr : it->second);
                    break;
                }
            }
        }
        model_.rules.push_back(std::move(r));
    }

    void draw(const ast::DrawDecl& decl, std::uint32_t file) {
        const ElementModel* type = nullptr;
        if (decl.header.empty()) {
            diagnostics_.error(decl.keyword, "'%draw' needs the name of the element type it draws");
        } else {
            if (decl.header.size() > 1) {
                diagnostics_.error(span(decl.header[1].where, decl.header.back().where),
                                   "'%draw' takes one element type name; unexpected " +
                                       quoted(decl.header[1].text));
            }
            type = lookup(decl.header.front());
        }
        if (type) {
            auto it = draws_.find(type->name);
            if (it != draws_.end()) {
                diagnostics_.error(decl.header.front().where,
                                   "duplicate '%draw' for element type " + quoted(type->name),
                                   {{it->second, "first '%draw " + type->name + "' here"}});
            } else {
                draws_.emplace(type->name, decl.header.front().where);
                model_.draws.push_back(DrawModel{&decl, file, type});
                const_cast<ElementModel*>(type)->draw = &decl;
            }
        }
        for (const ast::DollarToken& d : decl.body.dollars) {
            if (d.target == Target::bad) {
                diagnostics_.error(d.where, d.problem);
            } else if (d.target == Target::parent) {
                check_proxy_index(d, type);
            } else {
                diagnostics_.error(d.where, quoted(token_text(files_, d)) +
                                                " has no meaning in '%draw': only '$$', '$' and "
                                                "'$(k)', the drawn element and its proxies, do");
            }
        }
    }

    void param(const ast::ParamDecl& decl, std::uint32_t file) {
        if (decl.type.empty()) {
            diagnostics_.error(decl.name.where,
                               "'%param' needs a type and a name: '%param TYPE "
                               "NAME = DEFAULT;', as in '%param double size = 3.0;'");
            return;
        }
        std::string written;
        for (const ast::Name& w : decl.type) written += (written.empty() ? "" : " ") + w.text;
        auto type = find_param_type(written);
        if (!type) {
            diagnostics_.error(span(decl.type.front().where, decl.type.back().where),
                               "bad '%param' type " + quoted(written) + "; allowed types are " +
                                   std::string(param_type_list()));
        }
        bool declared = declare_global(decl.name, "parameter");
        if (type) {
            std::string why;
            if (!default_parses(*type, decl.default_value.text, why)) {
                diagnostics_.error(decl.default_value.where,
                                   "bad default " + quoted(decl.default_value.text) + " for " +
                                       quoted(written) + " parameter " + quoted(decl.name.text) +
                                       ": expected " + why);
                return;
            }
            if (decl.range && !range_ok(decl, *type, written)) return;
        }
        if (type && declared) model_.params.push_back(ParamModel{&decl, file, *type});
    }

    // `in [LO, HI]`: numeric types only, bounds of the parameter's type, LO < HI, default inside.
    bool range_ok(const ast::ParamDecl& decl, const ParamType& type, const std::string& written) {
        const ast::ParamRange& range = *decl.range;
        const std::string who = quoted(written) + " parameter " + quoted(decl.name.text);
        if (!is_numeric(type)) {
            diagnostics_.error(range.where, who +
                                                " cannot have a range: only int, long, float and "
                                                "double parameters can");
            return false;
        }
        bool ok = true;
        for (const ast::Name* bound : {&range.low, &range.high}) {
            std::string why;
            if (!default_parses(type, bound->text, why)) {
                diagnostics_.error(bound->where, "bad range bound " + quoted(bound->text) +
                                                     " for " + who + ": expected " + why);
                ok = false;
            }
        }
        if (!ok) return false;
        const long double low = numeric_value(range.low.text);
        const long double high = numeric_value(range.high.text);
        const std::string shown = "[" + range.low.text + ", " + range.high.text + "]";
        if (!(low < high)) {
            diagnostics_.error(range.where, "empty range " + shown + " for parameter " +
                                                quoted(decl.name.text) +
                                                ": the low bound must be less than the high one");
            return false;
        }
        const long double value = numeric_value(decl.default_value.text);
        if (value < low || value > high) {
            diagnostics_.error(decl.default_value.where,
                               "default " + quoted(decl.default_value.text) + " of parameter " +
                                   quoted(decl.name.text) + " is outside its range " + shown);
            return false;
        }
        return true;
    }

    void exhausted(const ast::ExhaustedDecl& decl, std::uint32_t file) {
        no_dollars(decl.body, "%exhausted");
        if (model_.exhausted) {
            diagnostics_.error(decl.keyword, "duplicate '%exhausted' section",
                               {{model_.exhausted->keyword, "first '%exhausted' here"}});
            return;
        }
        model_.exhausted = &decl;
        model_.exhausted_file = file;
    }

    void no_dollars(const ast::CodeBlock& code, std::string_view section) {
        for (const ast::DollarToken& d : code.dollars) {
            diagnostics_.error(d.where, quoted(token_text(files_, d)) + " has no meaning in '" +
                                            std::string(section) +
                                            "': dollar tokens belong in rule and %draw bodies");
        }
    }

    const SourceFiles& files_;
    Diagnostics& diagnostics_;
    PatternModel model_;
    std::map<std::string, std::pair<SourceRange, std::string>> globals_;
    std::set<const ElementModel*> incomplete_;
    std::size_t suggestion_budget_ = 1000000;
    std::map<std::string, SourceRange> draws_;
};

}  // namespace

PatternModel check_program(const RuleProgram& program, const SourceFiles& files,
                           Diagnostics& diagnostics) {
    return Checker(program, files, diagnostics).run();
}

}  // namespace acanthus
