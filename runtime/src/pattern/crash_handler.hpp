// Turns a crash inside user code (a stack overflow from endless recursion, a bad pointer, an
// integer division by zero) into exit 3 naming the rule, with no output left behind. Crashes
// outside user code keep the default behaviour.
#pragma once

namespace acanthus::detail {

// Installs an alternate signal stack and handlers for SIGSEGV, SIGBUS, SIGFPE and SIGABRT.
// Idempotent.
void install_crash_handler();

}  // namespace acanthus::detail
