// What the Flex scanner remembers between tokens: position, the section being collected,
// the C++ body's dollar tokens. Kept out of scanner.ll so the generated file stays thin.
#pragma once

#include <string>
#include <string_view>

#include "ast/code_block.hpp"
#include "brace_balance.hpp"
#include "diagnostics.hpp"
#include "source_range.hpp"

namespace acanthus {

enum class SectionKind { element, source, rule, draw, exhausted };

std::string_view section_keyword(SectionKind kind);  // "rule"
std::string_view end_keyword(SectionKind kind);      // "endrule"

class ScanState {
  public:
    static constexpr std::size_t kMaxDollarsPerBody = 100000;

    ScanState(std::uint32_t file, const std::string& text, Diagnostics& diagnostics);

    // Every match passes through here (YY_USER_ACTION): the token spans [begin, pos).
    void advance(const char* text, std::size_t length);
    // Gives back all but the first `keep` bytes of the last match (pairs with yyless).
    void give_back(const char* text, std::size_t keep);
    const SourceRange& token() const { return token_; }
    std::string_view token_text() const;

    // Sections with a C++ body.
    void open_section(SectionKind kind);  // at the section keyword token
    SectionKind section() const { return section_; }
    const SourceRange& section_keyword_range() const { return section_start_; }
    void begin_body_here();     // the body starts at the current token's first byte
    void begin_body_after();    // the body starts after the current token
    void begin_body_missing();  // %rule reached its end marker with no '{' body
    void add_dollar(std::string_view text);
    // Ends the body at the current token's first byte.
    ast::CodeBlock finish_body(bool terminated);
    SourceRange body_range() const;

    // An end marker or section keyword at the start of a line inside a body. Returns what to
    // do: 0 plain text (not a keyword), 1 the matching end marker, 2 a section keyword that
    // means the section was never closed (rescan it), 3 a mismatched end marker (error given).
    int classify_marker(std::string_view keyword);
    void report_unterminated_at_eof();

    // Header lines (%element, %draw, %rule preamble).
    bool header_seen = false;
    bool line_has_tokens = false;
    // A run of stray lines outside sections is reported once.
    bool in_stray = false;
    // Block comments: where the open one started, and the state to go back to.
    SourceRange comment_start;
    int comment_return = 0;
    // Braces of the body being collected.
    BraceBalance braces;
    void open_brace();
    void close_brace();
    // Raw string literal delimiter.
    std::string raw_delimiter;
    SourceRange raw_start;
    bool in_raw_string = false;
    bool in_block_comment = false;
    // The lookahead the parser just got was a BAD token already reported by the scanner.
    bool last_token_reported = false;
    std::uint32_t last_bad_line = 0;

    Diagnostics& diagnostics;

  private:
    // Indentation (columns of leading blanks) of the current token's line; cached per line so
    // a long line costs one scan.
    std::uint32_t current_line_indent();

    const std::string& text_;
    std::uint32_t indent_line_ = 0;
    std::uint32_t indent_ = 0;
    SourcePosition pos_;
    SourceRange token_;
    SectionKind section_ = SectionKind::element;
    SourceRange section_start_;
    ast::CodeBlock body_;
};

}  // namespace acanthus
