#include "app/crash_stack.h"

#include <dlfcn.h>
#include <elf.h>
#include <execinfo.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace gps {

namespace {

constexpr std::array<int, 5> kFatalSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
constexpr int kMaxFrames = 64;

// Set once when the report is installed: the handler itself allocates nothing and opens no file.
const char* program_name = "gpsurf";
char executable[4096] = {};
const void* executable_base = nullptr;  // where the program is loaded (dladdr's dli_fbase)
uintptr_t address_bias = 0;             // subtracted for addr2line: the base of a position-independent program
struct sigaction previous[NSIG];

void write_text(const char* text) {
  for (size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= size_t(n);
  }
}

// `value` in decimal or hexadecimal ("0x…") into `out` (room for 20 characters and the end).
void format_number(uintptr_t value, bool hex, char* out) {
  char digits[20];
  int n = 0;
  const unsigned base = hex ? 16 : 10;
  do {
    digits[n++] = "0123456789abcdef"[value % base];
    value /= base;
  } while (value > 0);
  if (hex) {
    *out++ = '0';
    *out++ = 'x';
  }
  while (n > 0) *out++ = digits[--n];
  *out = '\0';
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGBUS:
      return "SIGBUS";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGABRT:
      return "SIGABRT";
    default:
      return "signal";
  }
}

// Names the program's own frames among `frames` with addr2line (function, and file and line where the
// build has them), run in a child so that nothing here reads a file.
void name_program_frames(void* const* frames, int n) {
  static char offsets[kMaxFrames][24];
  const char* argv[kMaxFrames + 8];
  int a = 0;
  for (const char* option : {"addr2line", "-f", "-C", "-p", "-e"}) argv[a++] = option;
  argv[a++] = executable;
  const int first_address = a;
  for (int i = 0; i < n; ++i) {
    Dl_info info;
    if (dladdr(frames[i], &info) == 0 || info.dli_fbase != executable_base) continue;
    // A return address is the instruction after the call: one byte back is the call's line.
    format_number(reinterpret_cast<uintptr_t>(frames[i]) - address_bias - 1, true, offsets[a - first_address]);
    argv[a] = offsets[a - first_address];
    ++a;
  }
  argv[a] = nullptr;
  if (a == first_address || executable[0] == '\0') return;
  write_text("its own frames, named:\n");
  const pid_t child = ::fork();
  if (child == 0) {
    ::unsetenv("LD_PRELOAD");  // a sanitized run's preloads are not addr2line's
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    ::execvp(argv[0], const_cast<char* const*>(argv));
    ::_exit(127);
  }
  if (child > 0) ::waitpid(child, nullptr, 0);
}

void on_fatal_signal(int signal, siginfo_t*, void*) {
  // One report: a second thread that dies meanwhile waits for the first to end the program.
  static std::atomic<bool> reporting{false};
  if (reporting.exchange(true))
    for (;;) ::pause();
  // A crash inside the loader's or the unwinder's lock would hold the report up: the alarm ends it.
  ::alarm(30);
  char number[24];
  format_number(uintptr_t(signal), false, number);
  write_text(program_name);
  write_text(": fatal signal ");
  write_text(number);
  write_text(" (");
  write_text(signal_name(signal));
  write_text("); its stack, innermost first:\n");
  void* frames[kMaxFrames];
  const int n = ::backtrace(frames, kMaxFrames);
  ::backtrace_symbols_fd(frames, n, STDERR_FILENO);
  name_program_frames(frames, n);
  // On to the handler before: raised again, the signal waits until this handler returns.
  ::sigaction(signal, &previous[signal], nullptr);
  ::raise(signal);
}

// Whether the program is position-independent (ELF type ET_DYN): then addr2line takes its addresses
// less the base it is loaded at.
bool position_independent(const char* path) {
  std::ifstream in(path, std::ios::binary);
  Elf64_Ehdr header{};
  return in.read(reinterpret_cast<char*>(&header), sizeof(header)) && header.e_type == ET_DYN;
}

}  // namespace

void report_crash_stack_if_asked(const char* program) {
  const char* asked = std::getenv("GPSURF_CRASH_STACK");
  if (!asked || asked[0] == '\0') return;
  program_name = program;
  const ssize_t length = ::readlink("/proc/self/exe", executable, sizeof(executable) - 1);
  executable[length > 0 ? length : 0] = '\0';
  Dl_info self;
  if (dladdr(reinterpret_cast<const void*>(&report_crash_stack_if_asked), &self) != 0) executable_base = self.dli_fbase;
  if (executable[0] != '\0' && position_independent(executable))
    address_bias = reinterpret_cast<uintptr_t>(executable_base);
  void* warm[1];
  ::backtrace(warm, 1);  // its first call loads the unwinder, which allocates: not in the handler
  for (const int signal : kFatalSignals) {
    struct sigaction action {};
    action.sa_sigaction = on_fatal_signal;
    action.sa_flags = SA_SIGINFO;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, &previous[signal]);
  }
}

}  // namespace gps
