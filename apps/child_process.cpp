#include "apps/child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <system_error>

extern char** environ;

namespace argus::apps {

namespace {

// posix_spawn's file actions, released however start_process leaves.
class file_actions {
 public:
  file_actions() { posix_spawn_file_actions_init(&actions_); }
  ~file_actions() { posix_spawn_file_actions_destroy(&actions_); }
  file_actions(const file_actions&) = delete;
  file_actions& operator=(const file_actions&) = delete;
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

}  // namespace

pid_t start_process(const std::string& program, const std::vector<std::string>& arguments,
                    const std::filesystem::path& stdout_file,
                    const std::filesystem::path& stderr_file) {
  std::vector<std::string> words{program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  file_actions actions;
  const int flags = O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC;
  posix_spawn_file_actions_addopen(actions.get(), STDOUT_FILENO, stdout_file.c_str(), flags, 0644);
  posix_spawn_file_actions_addopen(actions.get(), STDERR_FILENO, stderr_file.c_str(), flags, 0644);
  posix_spawn_file_actions_addopen(actions.get(), STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int error =
      posix_spawn(&pid, program.c_str(), actions.get(), nullptr, argv.data(), environ);
  if (error != 0)
    throw std::system_error(error, std::generic_category(), "cannot start " + program);
  return pid;
}

std::optional<ended_process> wait_for_any_child() {
  int status = 0;
  rusage usage{};
  const pid_t pid = wait4(-1, &status, 0, &usage);
  if (pid <= 0) return std::nullopt;
  const long rss = usage.ru_maxrss;  // KiB on Linux
  if (WIFEXITED(status)) return ended_process{pid, WEXITSTATUS(status), rss};
  if (WIFSIGNALED(status)) return ended_process{pid, 128 + WTERMSIG(status), rss};
  return ended_process{pid, 255, rss};
}

std::string this_executable() {
  std::array<char, 4096> path{};
  const auto length = readlink("/proc/self/exe", path.data(), path.size() - 1);
  if (length <= 0) throw std::system_error(errno, std::generic_category(), "/proc/self/exe");
  return std::string(path.data(), static_cast<std::size_t>(length));
}

}  // namespace argus::apps
