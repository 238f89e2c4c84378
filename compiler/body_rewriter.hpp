// Rewrites the dollar tokens of a body into C++ that names the parent, children and goal,
// keeping every line where it was.
#pragma once

#include <string>
#include <string_view>

#include "ast/code_block.hpp"

namespace acanthus {

// `file_text` is the whole file the block comes from.
std::string rewrite_body(std::string_view file_text, const ast::CodeBlock& block);

// The C++ a single token becomes: `(*self_)`, `c1_->p0`, `x->p1`, `acanthus::body::goal()`.
std::string dollar_replacement(const ast::DollarToken& token);

}  // namespace acanthus
