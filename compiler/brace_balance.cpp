#include "brace_balance.hpp"

namespace acanthus {

void BraceBalance::open(const SourceRange& where, std::uint32_t indent) {
    if (open_.size() < kMaxTracked) open_.push_back({where, indent});
    ++depth_;
}

void BraceBalance::close(const SourceRange& where, std::uint32_t indent, Diagnostics& diagnostics,
                         const std::string& section) {
    if (depth_ == 0) {
        if (!reported_unmatched_)
            diagnostics.error(where, "unmatched '}' in the " + section + " body");
        reported_unmatched_ = true;
        return;
    }
    if (depth_ <= open_.size()) {
        if (!have_suspect_ && indent < open_.back().indent) {
            have_suspect_ = true;
            suspect_ = open_.back().where;
        }
        open_.pop_back();
    }
    --depth_;
}

void BraceBalance::finish(const SourceRange& end_marker, Diagnostics& diagnostics,
                          const std::string& section, const std::string& end_marker_name) {
    if (depth_ > 0 && !open_.empty()) {
        diagnostics.error(
            have_suspect_ ? suspect_ : open_.back().where,
            "unclosed '{' in the " + section + " body: no matching '}' before " + end_marker_name,
            {{end_marker, "the body ends here"}});
    }
    reset();
}

void BraceBalance::reset() {
    open_.clear();
    depth_ = 0;
    reported_unmatched_ = false;
    have_suspect_ = false;
    in_directive = false;
}

}  // namespace acanthus
