#pragma once
// Where the environment asks for it (GPSURF_CRASH_STACK set, as the tests' runs set it), a program
// that dies of a fatal signal first writes the signal and its stack, the program's frames named by
// addr2line, to stderr: a crash that does not come back, as in a CI run, still says where it was.

namespace gps {

/// Installs the report for SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT where GPSURF_CRASH_STACK is set
/// (else does nothing). After the report the signal goes on to the handler there was before (the
/// default, or a sanitizer's), so the program still dies of it. `program` names it in the report.
void report_crash_stack_if_asked(const char* program);

}  // namespace gps
