/* Scanner for Acanthus rule files (.acr).
 *
 * Outside sections only comments and blank lines are allowed. Section headers are tokenized;
 * C++ bodies are collected as one CODE token per section (a byte range of the file) while the
 * scanner notes every dollar token in them, skipping string, character and raw string literals
 * and comments. A line holding only an end marker (%endrule, ...) ends the body. Braces are
 * counted outside literals, comments and preprocessor lines: an unclosed '{' is reported.
 */
%option reentrant noyywrap nounput noinput batch
%option bison-bridge bison-locations
%option 8bit nodefault warn
%option never-interactive
%option extra-type="acanthus::ScanState*"
%option prefix="acr_yy"

%top{
#include "parse_driver.hpp"
#include "parser.hpp"
#include "scan_state.hpp"
}

%{
#include <string>
#include <string_view>

#define YYSTYPE acanthus::Parser::value_type
#define YYLTYPE acanthus::SourceRange

#undef YY_DECL
#define YY_DECL acanthus::Parser::symbol_type acr_yylex(YYSTYPE* yylval_param, YYLTYPE* yylloc_param, yyscan_t yyscanner)

#define YY_USER_ACTION                                                   \
    yyextra->advance(yytext, static_cast<std::size_t>(yyleng));          \
    *yylloc = yyextra->token();
/* Gives back all of the match but its first N bytes, keeping positions right. */
#define KEEP(N) do { yyextra->give_back(yytext, (N)); yyless(N); *yylloc = yyextra->token(); } while (0)
/* Gives back a whole match that started at the beginning of a line, to be rescanned. */
#define KEEP_LINE_START() do { KEEP(0); yy_set_bol(1); } while (0)

using acanthus::Parser;
using acanthus::SectionKind;

namespace {

Parser::symbol_type token_bad(acanthus::ScanState& s, std::string_view what) {
    std::string text(s.token_text());
    std::string shown;
    for (char c : text) {
        unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7f) {
            static const char hex[] = "0123456789abcdef";
            shown += "\\x";
            shown += hex[u >> 4];
            shown += hex[u & 15];
        } else {
            shown += c;
        }
    }
    // One complaint per line: the parser skips to the end of the section anyway.
    if (s.token().begin.line != s.last_bad_line) {
        s.diagnostics.error(s.token(), "unexpected '" + shown + "' " + std::string(what));
        s.last_bad_line = s.token().begin.line;
    }
    s.last_token_reported = true;
    return Parser::make_BAD(s.token());
}

// Where `in` starts a range inside an unquoted default ("3.0 in [0.5, 10]"): the offset of the
// blanks before it, or the text's size when there is none.
std::size_t range_start(std::string_view text) {
    for (std::size_t i = 1; i + 2 <= text.size(); ++i) {
        bool blank_before = text[i - 1] == ' ' || text[i - 1] == '\t';
        if (!blank_before || text.compare(i, 2, "in") != 0) continue;
        bool ends = i + 2 == text.size() || text[i + 2] == ' ' || text[i + 2] == '\t' ||
                    text[i + 2] == '[';
        if (!ends) continue;
        std::size_t cut = i;
        while (cut > 0 && (text[cut - 1] == ' ' || text[cut - 1] == '\t')) --cut;
        return cut;
    }
    return text.size();
}

std::string keyword_of(std::string_view match) {
    std::size_t p = match.find('%');
    return std::string(match.substr(p + 1));
}

}  // namespace
%}

ID          [A-Za-z_][A-Za-z0-9_]*
WS          [ \t\r\f\v]
DIGITS      [0-9]+
BADRUN      [^A-Za-z0-9_ \t\r\f\v\n\0{*/;="]+

%x OCOMMENT ELEMENT_HEAD RULE_HEAD PARAM_LINE PARAM_VALUE PARAM_RANGE IMPORT_LINE KEYWORD_REST
%x BODY BODY_COMMENT BODY_RAW AFTER_END

%%

%{
    yyextra->last_token_reported = false;
%}

<INITIAL>{
{WS}+                   { }
\n                      { }
"//"[^\n\0]*              { }
"/*"                    { yyextra->comment_start = yyextra->token(); yyextra->comment_return = INITIAL; BEGIN(OCOMMENT); }
"%element"              { yyextra->open_section(SectionKind::element); BEGIN(ELEMENT_HEAD); return Parser::make_ELEMENT(yyextra->token()); }
"%draw"                 { yyextra->open_section(SectionKind::draw); BEGIN(ELEMENT_HEAD); return Parser::make_DRAW(yyextra->token()); }
"%rule"                 { yyextra->open_section(SectionKind::rule); BEGIN(RULE_HEAD); return Parser::make_RULE(yyextra->token()); }
"%source"               { yyextra->open_section(SectionKind::source); BEGIN(KEYWORD_REST); return Parser::make_SOURCE(yyextra->token()); }
"%exhausted"            { yyextra->open_section(SectionKind::exhausted); BEGIN(KEYWORD_REST); return Parser::make_EXHAUSTED(yyextra->token()); }
"%param"                { yyextra->in_stray = false; BEGIN(PARAM_LINE); return Parser::make_PARAM(yyextra->token()); }
"%import"               { yyextra->in_stray = false; BEGIN(IMPORT_LINE); return Parser::make_IMPORT(yyextra->token()); }
"%"(endelement|endsource|endrule|enddraw|endexhausted) {
                          std::string k = keyword_of(yytext);
                          yyextra->diagnostics.error(yyextra->token(), "'%" + k + "' without an open '%" + k.substr(3) + "' section");
                        }
"%"{ID}?                { yyextra->diagnostics.error(yyextra->token(), "unknown directive '" + std::string(yytext) + "'; sections are %element, %source, %rule, %draw, %param, %import and %exhausted"); }
"/"                     |
[^/ \t\r\f\v\n%][^\n\0]*  {
                          if (!yyextra->in_stray) {
                              yyextra->in_stray = true;
                              acanthus::SourceRange r = yyextra->token();
                              /* Underline the first word, not the whole line. */
                              std::size_t word = std::string_view(yytext, yyleng).find_first_of(" \t\r\f\v");
                              if (word != std::string_view::npos) {
                                  r.end = r.begin;
                                  r.end.column += static_cast<std::uint32_t>(word);
                                  r.end.offset += word;
                              }
                              yyextra->diagnostics.error(r, "expected a section ('%element', '%rule', '%source', ...) or a comment outside sections");
                          }
                        }
<<EOF>>                 { return Parser::make_END(yyextra->token()); }
}

<OCOMMENT>{
"*/"                    { BEGIN(yyextra->comment_return); }
[^*\n\0]+               { }
\n|\0                   { }
"*"                     { }
<<EOF>>                 {
                          yyextra->diagnostics.error(yyextra->comment_start, "unterminated comment");
                          if (yyextra->comment_return == INITIAL) return Parser::make_END(yyextra->token());
                          BEGIN(yyextra->comment_return);
                        }
}

    /* Header of %element and %draw: the first non-blank line holds the names. */
<ELEMENT_HEAD>{
{WS}+                   { }
"//"[^\n\0]*              { }
"/*"                    { yyextra->comment_start = yyextra->token(); yyextra->comment_return = ELEMENT_HEAD; BEGIN(OCOMMENT); }
{ID}                    { yyextra->header_seen = true; return Parser::make_IDENT(yytext, yyextra->token()); }
\n                      {
                          /* %element may put its header on the next line; %draw may not. */
                          if (yyextra->header_seen || yyextra->section() == SectionKind::draw) {
                              yyextra->begin_body_after();
                              BEGIN(BODY);
                              return Parser::make_HEAD_END(yyextra->token());
                          }
                        }
^{WS}*"%"{ID}           { KEEP_LINE_START(); yyextra->begin_body_here(); BEGIN(BODY); return Parser::make_HEAD_END(yyextra->token()); }
{BADRUN}|.              { return token_bad(*yyextra, yyextra->section() == SectionKind::draw ? "in a '%draw' header; expected the element type to draw" : "in an '%element' header; expected a type name and proxy kinds"); }
<<EOF>>                 { yyextra->begin_body_here(); BEGIN(BODY); return Parser::make_HEAD_END(yyextra->token()); }
}

    /* Rule preamble: parent --> children, then `* var type` lines, then the '{' body. */
<RULE_HEAD>{
{WS}+                   { }
"//"[^\n\0]*              { }
"/*"                    { yyextra->comment_start = yyextra->token(); yyextra->comment_return = RULE_HEAD; BEGIN(OCOMMENT); }
{ID}                    { yyextra->line_has_tokens = true; return Parser::make_IDENT(yytext, yyextra->token()); }
"-->"                   { yyextra->line_has_tokens = true; return Parser::make_ARROW(yyextra->token()); }
"*"                     { yyextra->line_has_tokens = true; return Parser::make_STAR(yyextra->token()); }
\n                      {
                          if (yyextra->line_has_tokens) {
                              yyextra->line_has_tokens = false;
                              return Parser::make_HEAD_EOL(yyextra->token());
                          }
                        }
"{"                     {
                          KEEP(0);
                          if (yyextra->line_has_tokens) {
                              yyextra->line_has_tokens = false;
                              return Parser::make_HEAD_EOL(yyextra->token());
                          }
                          yyextra->begin_body_here();
                          BEGIN(BODY);
                        }
^{WS}*"%"{ID}           { KEEP_LINE_START(); yyextra->begin_body_missing(); BEGIN(BODY); }
{BADRUN}|.              { yyextra->line_has_tokens = true; return token_bad(*yyextra, "in a rule preamble; expected 'parent --> child ...', '* var type' or '{'"); }
<<EOF>>                 {
                          if (yyextra->line_has_tokens) {
                              yyextra->line_has_tokens = false;
                              return Parser::make_HEAD_EOL(yyextra->token());
                          }
                          yyextra->begin_body_missing();
                          BEGIN(BODY);
                        }
}

    /* %param TYPE NAME = DEFAULT; */
<PARAM_LINE>{
{WS}+                   { }
"//"[^\n\0]*              { }
{ID}("::"{ID})*         { return Parser::make_IDENT(yytext, yyextra->token()); }
"="                     { BEGIN(PARAM_VALUE); return Parser::make_EQUALS(yyextra->token()); }
";"                     { return Parser::make_SEMI(yyextra->token()); }
\n                      { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
[^ \t\r\f\v\n\0;=/]+|.   { return token_bad(*yyextra, "in a '%param' line; expected 'TYPE NAME = DEFAULT;'"); }
<<EOF>>                 { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
}

<PARAM_VALUE>{
{WS}+                   { }
\"([^"\\\n\0]|\\.)*\"     { BEGIN(PARAM_RANGE); return Parser::make_DEFAULT_TEXT(yytext, yyextra->token()); }
[^ \t\r\f\v\n\0;"/]+({WS}+[^ \t\r\f\v\n\0;"/]+)* {
                          /* The default ends where a range begins: `3.0 in [0.5, 10]`. */
                          std::size_t cut = range_start(std::string_view(yytext, static_cast<std::size_t>(yyleng)));
                          if (cut < static_cast<std::size_t>(yyleng)) KEEP(static_cast<int>(cut));
                          BEGIN(PARAM_RANGE);
                          return Parser::make_DEFAULT_TEXT(yytext, yyextra->token());
                        }
.|\n                    { KEEP(0); BEGIN(PARAM_LINE); }
<<EOF>>                 { BEGIN(PARAM_LINE); }
}

    /* after the default: an optional `in [LO, HI]`, then ';' */
<PARAM_RANGE>{
{WS}+                   { }
"//"[^\n\0]*              { }
"in"                    { return Parser::make_IN(yyextra->token()); }
"["                     { return Parser::make_LBRACKET(yyextra->token()); }
"]"                     { return Parser::make_RBRACKET(yyextra->token()); }
","                     { return Parser::make_COMMA(yyextra->token()); }
";"                     { BEGIN(PARAM_LINE); return Parser::make_SEMI(yyextra->token()); }
\n                      { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
[^ \t\r\f\v\n\0;,\[\]/]+  { return Parser::make_BOUND(yytext, yyextra->token()); }
.                       { return token_bad(*yyextra, "in a '%param' line; expected 'in [LO, HI]' or ';'"); }
<<EOF>>                 { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
}

    /* %import "name" */
<IMPORT_LINE>{
{WS}+                   { }
"//"[^\n\0]*              { }
\"[^"\n\0]*\"             { std::string t(yytext + 1, yyleng - 2); return Parser::make_STRING(t, yyextra->token()); }
\n                      { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
\"[^"\n\0]*               { return token_bad(*yyextra, "in an '%import' line: the name has no closing quote"); }
[^ \t\r\f\v\n\0"/]+|.    { return token_bad(*yyextra, "in an '%import' line; expected a quoted name"); }
<<EOF>>                 { BEGIN(INITIAL); return Parser::make_LINE_END(yyextra->token()); }
}

    /* The rest of the %source or %exhausted line. */
<KEYWORD_REST>{
{WS}+                   { }
"//"[^\n\0]*              { }
\n                      { yyextra->begin_body_after(); BEGIN(BODY); }
[^ \t\r\f\v\n][^\n\0]*    {
                          yyextra->diagnostics.error(yyextra->token(), "unexpected text after '%" + std::string(acanthus::section_keyword(yyextra->section())) + "'; the body starts on the next line");
                        }
<<EOF>>                 { yyextra->begin_body_here(); BEGIN(BODY); }
}

    /* End markers and section keywords at the start of a line, in any body state. */
<BODY,BODY_COMMENT,BODY_RAW>^{WS}*"%"{ID} {
                          switch (yyextra->classify_marker(keyword_of(yytext))) {
                          case 1:
                          case 3: {
                              acanthus::SourceRange where = yyextra->body_range();
                              BEGIN(AFTER_END);
                              return Parser::make_CODE(yyextra->finish_body(true), where);
                          }
                          case 2: {
                              KEEP_LINE_START();
                              acanthus::SourceRange where = yyextra->body_range();
                              BEGIN(INITIAL);
                              return Parser::make_CODE(yyextra->finish_body(false), where);
                          }
                          default:
                              break;
                          }
                        }
<BODY,BODY_COMMENT,BODY_RAW><<EOF>> {
                          yyextra->report_unterminated_at_eof();
                          acanthus::SourceRange where = yyextra->body_range();
                          BEGIN(INITIAL);
                          return Parser::make_CODE(yyextra->finish_body(false), where);
                        }

<BODY>{
"$$"{DIGITS}            { yyextra->add_dollar(yytext); }
"$$"{ID}                { yyextra->add_dollar(yytext); }
"$$"                    { yyextra->add_dollar(yytext); }
"$"{DIGITS}"("{DIGITS}")" { yyextra->add_dollar(yytext); }
"$"{DIGITS}             { yyextra->add_dollar(yytext); }
"$"{ID}"("{DIGITS}")"   { yyextra->add_dollar(yytext); }
"$"{ID}                 { yyextra->add_dollar(yytext); }
"$("{DIGITS}")"         { yyextra->add_dollar(yytext); }
"$"({DIGITS}|{ID})?"("  { yyextra->add_dollar(yytext); }
"$"                     { yyextra->add_dollar(yytext); }
(u8|u|U|L)?R\"[^()\\ \t\v\f\r\n"]{0,16}"(" {
                          std::string_view t(yytext, yyleng);
                          std::size_t q = t.find('"');
                          yyextra->raw_delimiter = ")" + std::string(t.substr(q + 1, t.size() - q - 2)) + "\"";
                          yyextra->raw_start = yyextra->token();
                          yyextra->in_raw_string = true;
                          BEGIN(BODY_RAW);
                        }
(u8|u|U|L)?\"([^"\\\n\0]|\\(.|\n))*\"? { }
(u8|u|U|L)?'([^'\\\n\0]|\\(.|\n))*'?   { }
{ID}                    { }
"."?[0-9]([0-9A-Za-z_.]|'[0-9A-Za-z_]|[eEpP][+-])* { }
"//"[^\n\0]*              { }
"/*"                    { yyextra->comment_start = yyextra->token(); yyextra->in_block_comment = true; BEGIN(BODY_COMMENT); }
"{"                     { yyextra->open_brace(); }
"}"                     { yyextra->close_brace(); }
^{WS}*"#"               { yyextra->braces.in_directive = true; }
"\\"{WS}*\n             { }
{WS}+                   { }
\n                      { yyextra->braces.in_directive = false; }
.                       { }
}

<BODY_COMMENT>{
"*/"                    { yyextra->in_block_comment = false; BEGIN(BODY); }
[^*%\n\0]+                { }
"*"|"%"|\n|\0          { }
}

<BODY_RAW>{
")"[^()\\ \t\v\f\r\n"]{0,16}\" {
                          if (std::string_view(yytext, yyleng) == yyextra->raw_delimiter) {
                              yyextra->in_raw_string = false;
                              BEGIN(BODY);
                          } else {
                              KEEP(1);
                          }
                        }
[^)%\n\0]+                { }
")"|"%"|\n|\0          { }
}

    /* The rest of an end marker's line. */
<AFTER_END>{
{WS}+                   { }
"//"[^\n\0]*              { }
"/*"                    { yyextra->comment_start = yyextra->token(); yyextra->comment_return = AFTER_END; BEGIN(OCOMMENT); }
\n                      { BEGIN(INITIAL); }
[^ \t\r\f\v\n/][^\n\0]*|"/" {
                          yyextra->diagnostics.error(yyextra->token(), "unexpected text after the end of the section");
                        }
<<EOF>>                 { BEGIN(INITIAL); }
}

%%

namespace acanthus {

Parser::symbol_type next_token(void* scanner) {
    Parser::value_type value;
    SourceRange location;
    return acr_yylex(&value, &location, scanner);
}

}  // namespace acanthus
