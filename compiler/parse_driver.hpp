// Parses one rule file into an ast::RuleFile; the Bison actions call back into it.
#pragma once

#include <memory>

#include "ast/rule_file.hpp"
#include "diagnostics.hpp"
#include "source_files.hpp"

namespace acanthus {

class ParseDriver {
  public:
    ParseDriver(const SourceFiles& files, Diagnostics& diagnostics)
        : files_(files), diagnostics_(diagnostics) {}

    // Scans and parses file `index`. Syntax errors go to the diagnostics; the returned file
    // holds every section that parsed (recovery resumes at the next section).
    std::unique_ptr<ast::RuleFile> parse(std::uint32_t index);

    // Called by parser actions.
    void add(ast::Section section) { file_->sections.push_back(std::move(section)); }
    void syntax_error(const SourceRange& where, const std::string& message);
    Diagnostics& diagnostics() { return diagnostics_; }
    // Set by the scanner when the lookahead is a bad token it has already reported.
    bool lookahead_reported() const;

  private:
    const SourceFiles& files_;
    Diagnostics& diagnostics_;
    std::unique_ptr<ast::RuleFile> file_;
    void* scanner_ = nullptr;
};

}  // namespace acanthus
