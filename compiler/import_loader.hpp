// Loads a rule file and, recursively, the files it imports: each once, cycles reported at the
// %import line, lookup in the importing file's directory, the -I directories, then the stdlib.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ast/rule_file.hpp"
#include "diagnostics.hpp"
#include "rule_program.hpp"
#include "source_files.hpp"

namespace acanthus {

class ImportLoader {
  public:
    ImportLoader(SourceFiles& files, Diagnostics& diagnostics,
                 std::vector<std::string> include_dirs, std::vector<std::string> stdlib_dirs);

    // Parses `path` and everything it imports. False when `path` itself cannot be read (the
    // message is in `error`); syntax and import errors go to the diagnostics.
    bool load(const std::string& path, std::string& error);
    // The sections in rule order.
    RuleProgram program() const;

    // Where "name" resolves from a file in `from_dir`; empty when nowhere.
    std::string resolve(const std::string& name, const std::string& from_dir) const;

  private:
    const ast::RuleFile* load_file(std::uint32_t index, const std::string& canonical);
    void flatten(const ast::RuleFile& file, RuleProgram& out) const;

    SourceFiles& files_;
    Diagnostics& diagnostics_;
    std::vector<std::string> include_dirs_;
    std::vector<std::string> stdlib_dirs_;
    std::vector<std::unique_ptr<ast::RuleFile>> parsed_;
    enum class State { loading, done };
    std::map<std::string, State> seen_;  // canonical path -> state
    std::uint32_t main_file_ = 0;
    int depth_ = 0;
};

}  // namespace acanthus
