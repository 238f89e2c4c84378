#include "scan_state.hpp"

#include <cerrno>
#include <cstdlib>

namespace acanthus {

std::string_view section_keyword(SectionKind kind) {
    switch (kind) {
        case SectionKind::element:
            return "element";
        case SectionKind::source:
            return "source";
        case SectionKind::rule:
            return "rule";
        case SectionKind::draw:
            return "draw";
        case SectionKind::exhausted:
            return "exhausted";
    }
    return "";
}

std::string_view end_keyword(SectionKind kind) {
    switch (kind) {
        case SectionKind::element:
            return "endelement";
        case SectionKind::source:
            return "endsource";
        case SectionKind::rule:
            return "endrule";
        case SectionKind::draw:
            return "enddraw";
        case SectionKind::exhausted:
            return "endexhausted";
    }
    return "";
}

namespace {

bool is_opening_keyword(std::string_view k) {
    return k == "element" || k == "source" || k == "rule" || k == "draw" || k == "exhausted" ||
           k == "param" || k == "import";
}

bool is_end_keyword(std::string_view k) {
    return k == "endelement" || k == "endsource" || k == "endrule" || k == "enddraw" ||
           k == "endexhausted";
}

// Parses a decimal index; -1 when it does not fit comfortably.
long parse_index(std::string_view digits) {
    if (digits.empty() || digits.size() > 9) return -1;
    long value = 0;
    for (char c : digits) value = value * 10 + (c - '0');
    return value;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

ScanState::ScanState(std::uint32_t file, const std::string& text, Diagnostics& d)
    : diagnostics(d), text_(text) {
    pos_.file = file;
    token_.begin = token_.end = pos_;
}

void ScanState::advance(const char* text, std::size_t length) {
    token_.begin = pos_;
    for (std::size_t i = 0; i < length; ++i) {
        if (text[i] == '\n') {
            ++pos_.line;
            pos_.column = 1;
        } else {
            ++pos_.column;
        }
    }
    pos_.offset += length;
    token_.end = pos_;
}

void ScanState::give_back(const char* text, std::size_t keep) {
    SourcePosition begin = token_.begin;
    pos_ = begin;
    advance(text, keep);
    token_.begin = begin;
}

std::string_view ScanState::token_text() const {
    return std::string_view(text_).substr(token_.begin.offset,
                                          token_.end.offset - token_.begin.offset);
}

void ScanState::open_section(SectionKind kind) {
    section_ = kind;
    section_start_ = token_;
    header_seen = false;
    line_has_tokens = false;
    in_stray = false;
    in_raw_string = false;
    in_block_comment = false;
}

void ScanState::begin_body_here() {
    braces.reset();
    body_ = ast::CodeBlock{};
    body_.begin = token_.begin;
}

void ScanState::begin_body_after() {
    braces.reset();
    body_ = ast::CodeBlock{};
    body_.begin = token_.end;
}

void ScanState::begin_body_missing() {
    begin_body_here();
    body_.present = false;
}

void ScanState::add_dollar(std::string_view text) {
    using Target = ast::DollarToken::Target;
    // A resource bound for pathological input; real bodies have a few dozen tokens.
    if (body_.dollars.size() >= kMaxDollarsPerBody) {
        if (body_.dollars.size() == kMaxDollarsPerBody) {
            ast::DollarToken d;
            d.target = Target::bad;
            d.where = token_;
            d.problem = "more than " + std::to_string(kMaxDollarsPerBody) +
                        " dollar tokens in one section; the rest are not checked";
            body_.dollars.push_back(std::move(d));
        }
        return;
    }
    ast::DollarToken d;
    d.where = token_;
    std::size_t i = 1;
    if (text.size() > 1 && text[1] == '$') {
        d.element = true;
        i = 2;
    }
    std::string_view rest = text.substr(i);
    // Split off "(k)" or a bare "(" (a bad proxy index).
    std::string_view name = rest;
    std::string_view index;
    bool open_paren = false;
    if (std::size_t paren = rest.find('('); paren != std::string_view::npos) {
        name = rest.substr(0, paren);
        open_paren = true;
        std::string_view inside = rest.substr(paren + 1);
        if (!inside.empty() && inside.back() == ')') index = inside.substr(0, inside.size() - 1);
    }
    if (name.empty()) {
        d.target = Target::parent;
    } else if (is_digit(name[0])) {
        d.target = Target::child;
        d.child = parse_index(name);
    } else if (name == "goal") {
        d.target = Target::goal;
        if (d.element) {
            d.target = Target::bad;
            d.problem = "'$$goal' is not a dollar token; the empty circle is '$goal'";
        }
    } else {
        d.target = Target::var;
        d.var = std::string(name);
    }
    if (open_paren && d.target != Target::bad) {
        if (index.empty() || d.element) {
            d.target = Target::bad;
            d.problem = "a proxy index after '" + std::string(text.substr(0, text.find('('))) +
                        "' must be an integer literal in parentheses, as in '" +
                        std::string(text.substr(0, text.find('('))) + "(1)'";
        } else if (d.target == Target::goal) {
            d.target = Target::bad;
            d.problem = "'$goal' has no proxies; use '$goal.center' and '$goal.radius'";
        } else {
            d.explicit_proxy = true;
            d.proxy = parse_index(index);
        }
    }
    body_.dollars.push_back(std::move(d));
}

std::uint32_t ScanState::current_line_indent() {
    if (token_.begin.line != indent_line_) {
        std::size_t start = token_.begin.offset - (token_.begin.column - 1);
        std::uint32_t indent = 0;
        for (std::size_t i = start; i < text_.size() && (text_[i] == ' ' || text_[i] == '\t'); ++i)
            indent += text_[i] == '\t' ? 8 - indent % 8 : 1;
        indent_line_ = token_.begin.line;
        indent_ = indent;
    }
    return indent_;
}

void ScanState::open_brace() {
    if (!braces.in_directive) braces.open(token_, current_line_indent());
}

void ScanState::close_brace() {
    if (!braces.in_directive)
        braces.close(token_, current_line_indent(), diagnostics,
                     "'%" + std::string(section_keyword(section_)) + "'");
}

ast::CodeBlock ScanState::finish_body(bool terminated) {
    if (terminated)
        braces.finish(token_, diagnostics, "'%" + std::string(section_keyword(section_)) + "'",
                      "'%" + std::string(end_keyword(section_)) + "'");
    else
        braces.reset();
    body_.end = token_.begin;
    body_.terminated = terminated;
    ast::CodeBlock out = std::move(body_);
    body_ = ast::CodeBlock{};
    return out;
}

SourceRange ScanState::body_range() const { return SourceRange{body_.begin, token_.begin}; }

int ScanState::classify_marker(std::string_view keyword) {
    std::string open = "'%" + std::string(section_keyword(section_)) + "'";
    std::string close = "'%" + std::string(end_keyword(section_)) + "'";
    if (keyword == end_keyword(section_)) return 1;
    if (is_end_keyword(keyword)) {
        diagnostics.error(token_,
                          "'%" + std::string(keyword) + "' does not close the " + open +
                              " section; expected " + close,
                          {{section_start_, open + " section starts here"}});
        return 3;
    }
    if (is_opening_keyword(keyword)) {
        diagnostics.error(
            section_start_, "unterminated " + open + " section",
            {{token_, "expected " + close + " before '%" + std::string(keyword) + "'"}});
        return 2;
    }
    return 0;
}

void ScanState::report_unterminated_at_eof() {
    std::string open = "'%" + std::string(section_keyword(section_)) + "'";
    std::string close = "'%" + std::string(end_keyword(section_)) + "'";
    std::vector<Note> notes;
    if (in_block_comment)
        notes.push_back({comment_start, "a '/*' comment opened here is still open"});
    if (in_raw_string)
        notes.push_back({raw_start, "a raw string literal opened here is still open"});
    diagnostics.error(
        section_start_,
        "unterminated " + open + " section: no " + close + " before the end of the file",
        std::move(notes));
}

}  // namespace acanthus
