#include "output/dsc_rewriter.hpp"

namespace acanthus::detail {

namespace {
constexpr std::string_view end_of_header = "%%EndPageSetup";
}

DscRewriter::DscRewriter(std::vector<std::pair<std::string, std::string>> replacements, Sink sink)
    : pending_(std::move(replacements)), sink_(std::move(sink)) {}

void DscRewriter::line(std::string_view text) {
    if (text.substr(0, end_of_header.size()) == end_of_header) header_ = false;
    for (auto it = pending_.begin(); it != pending_.end(); ++it) {
        if (text.substr(0, it->first.size()) != it->first) continue;
        const bool newline = !text.empty() && text.back() == '\n';
        sink_(it->first + " " + it->second + (newline ? "\n" : ""));
        pending_.erase(it);
        return;
    }
    sink_(text);
}

void DscRewriter::write(std::string_view bytes) {
    while (!bytes.empty() && header_ && !pending_.empty()) {
        const std::size_t end = bytes.find('\n');
        if (end == std::string_view::npos) {
            partial_.append(bytes);
            return;
        }
        partial_.append(bytes.substr(0, end + 1));
        bytes.remove_prefix(end + 1);
        std::string whole;
        whole.swap(partial_);
        line(whole);
    }
    if (!bytes.empty()) sink_(bytes);
}

void DscRewriter::finish() {
    if (partial_.empty()) return;
    std::string rest;
    rest.swap(partial_);
    if (header_ && !pending_.empty())
        line(rest);
    else
        sink_(rest);
}

}  // namespace acanthus::detail
