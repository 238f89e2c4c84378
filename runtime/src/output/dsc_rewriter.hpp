// PostScript's DSC header comments rewritten in a file streamed through, so that Cairo's PS and
// EPS go to disk as they are written: only the lines up to the page setup are looked at.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace acanthus::detail {

class DscRewriter {
  public:
    using Sink = std::function<void(std::string_view)>;
    // Each (key, value): the first line starting with `key` (e.g. "%%CreationDate:") becomes
    // "key value". Lines are looked at up to "%%EndPageSetup"; the rest passes through as it is.
    DscRewriter(std::vector<std::pair<std::string, std::string>> replacements, Sink sink);

    void write(std::string_view bytes);
    // Passes on an unterminated last header line.
    void finish();

  private:
    void line(std::string_view text);  // one header line, with its '\n' when it has one

    std::vector<std::pair<std::string, std::string>> pending_;
    Sink sink_;
    std::string partial_;
    bool header_ = true;
};

}  // namespace acanthus::detail
