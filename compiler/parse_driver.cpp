#include "parse_driver.hpp"

#include "parser.hpp"
#include "scan_state.hpp"

// The Flex scanner's C interface (prefix acr_yy).
using yyscan_t = void*;
struct yy_buffer_state;
int acr_yylex_init_extra(acanthus::ScanState* extra, yyscan_t* scanner);
int acr_yylex_destroy(yyscan_t scanner);
yy_buffer_state* acr_yy_scan_bytes(const char* bytes, int length, yyscan_t scanner);
acanthus::ScanState* acr_yyget_extra(yyscan_t scanner);

namespace acanthus {

std::unique_ptr<ast::RuleFile> ParseDriver::parse(std::uint32_t index) {
    file_ = std::make_unique<ast::RuleFile>();
    file_->file = index;
    const std::string& text = files_[index].text();
    ScanState state(index, text, diagnostics_);
    if (text.size() > static_cast<std::size_t>(INT32_MAX) - 2) {
        diagnostics_.file_error(index, "file too large");
        return std::move(file_);
    }
    yyscan_t scanner = nullptr;
    if (acr_yylex_init_extra(&state, &scanner) != 0) {
        diagnostics_.file_error(index, "cannot start the scanner");
        return std::move(file_);
    }
    scanner_ = scanner;
    acr_yy_scan_bytes(text.data(), static_cast<int>(text.size()), scanner);
    Parser parser(scanner, *this);
    parser.parse();
    acr_yylex_destroy(scanner);
    scanner_ = nullptr;
    return std::move(file_);
}

bool ParseDriver::lookahead_reported() const {
    return scanner_ && acr_yyget_extra(scanner_)->last_token_reported;
}

void ParseDriver::syntax_error(const SourceRange& where, const std::string& message) {
    if (lookahead_reported()) return;  // the scanner already said what is wrong
    diagnostics_.error(where, message);
}

}  // namespace acanthus
