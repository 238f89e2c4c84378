// report_partial (<acanthus/partial_picture.hpp>): forwarded to the running program's --partial
// pictures, when it draws them. Rule bodies run on the growth's thread only.
#include <acanthus/partial_picture.hpp>

namespace acanthus {

namespace {

detail::PartialHandler g_handler = nullptr;
void* g_context = nullptr;

}  // namespace

void report_partial(long placed, const PartialElements& extra) {
    if (g_handler) g_handler(g_context, placed, extra);
}

namespace detail {

void set_partial_handler(PartialHandler handler, void* context) noexcept {
    g_handler = handler;
    g_context = context;
}

}  // namespace detail

}  // namespace acanthus
