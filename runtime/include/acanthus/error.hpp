// Errors that map to the program's exit codes: 1 bad input, 2 bad usage, 3 rule failure.
#pragma once

#include <stdexcept>
#include <string>

namespace acanthus {

// Bad input (region, parameter, reference file): exit 1. `what()` is the full message,
// already naming the file (and element or line) where there is one.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Bad command line: exit 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A rule failed at run time (exception, NaN coordinates, unset proxy): exit 3.
class RuleFailure : public std::runtime_error {
  public:
    RuleFailure(const std::string& file, int line, const std::string& rule, const std::string& why)
        : std::runtime_error(file + ":" + std::to_string(line) + ": rule '" + rule + "': " + why),
          file_(file),
          line_(line),
          rule_(rule) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& rule() const { return rule_; }

  private:
    std::string file_;
    int line_;
    std::string rule_;
};

}  // namespace acanthus
