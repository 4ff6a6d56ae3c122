#pragma once
// Writing a file so that the target is either the old file or the complete new one (docs/design.md §4).
#include <functional>
#include <ostream>
#include <string>

namespace gps {

/// Writes through `write` into a temporary file beside `path` (".NAME.tmpPID"), flushes it to disk,
/// renames it over `path` and flushes the folder. A symbolic link is written through (the link stays).
/// What is there is checked before anything is written (core/io/save_target.h): a loop of links, a
/// directory, FIFO, device or socket, and a read-only file are refused. A file with other hard links
/// is written in place from the complete temporary file after its old contents are kept as NAME~
/// beside it, so that the links stay; an ending signal during that copy puts the old contents back
/// before it ends the process.
/// On any failure, or SIGINT/SIGTERM/SIGHUP/SIGQUIT meanwhile, the temporary file is removed and `path`
/// is untouched; gps::Error names it. Temporary files of this naming left by dead processes are removed.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

}  // namespace gps
