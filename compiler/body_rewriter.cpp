#include "body_rewriter.hpp"

namespace acanthus {

std::string dollar_replacement(const ast::DollarToken& d) {
    using Target = ast::DollarToken::Target;
    std::string holder;
    switch (d.target) {
        case Target::parent:
            holder = "self_";
            break;
        case Target::child:
            holder = std::string("c").append(std::to_string(d.child)).append("_");
            break;
        case Target::var:
            holder = d.var;
            break;
        case Target::goal:
            return "acanthus::body::goal()";
        case Target::bad:
            return "";
    }
    if (d.element) return "(*" + holder + ")";
    return holder + "->p" + std::to_string(d.proxy);
}

std::string rewrite_body(std::string_view file_text, const ast::CodeBlock& block) {
    std::string out;
    std::size_t from = block.begin.offset;
    for (const ast::DollarToken& d : block.dollars) {
        out.append(file_text.substr(from, d.where.begin.offset - from));
        out += dollar_replacement(d);
        from = d.where.end.offset;
    }
    out.append(file_text.substr(from, block.end.offset - from));
    return out;
}

}  // namespace acanthus
