#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace argus::apps {

/// Starts `program` with `arguments` (argv[1..]) as a child process, its stdout and stderr
/// written to the two files; returns its process id. Throws std::system_error when it cannot
/// start.
pid_t start_process(const std::string& program, const std::vector<std::string>& arguments,
                    const std::filesystem::path& stdout_file,
                    const std::filesystem::path& stderr_file);

/// A child that ended, and how: its exit code, or 128 + the signal that killed it (as shells
/// report it).
struct ended_process {
  pid_t pid = 0;
  int exit_status = 0;
  /// Its peak resident memory (the kernel's maximum resident set size), in KiB.
  long max_rss_kib = 0;
};

/// Waits for any child to end; nothing when a signal interrupted the wait or no child is left.
std::optional<ended_process> wait_for_any_child();

/// The path of the running executable (/proc/self/exe), to start more of itself.
std::string this_executable();

}  // namespace argus::apps
