#include "tests/support/fissure_command.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fissure::testing {

namespace {

/// The shell command that runs `fissure ARGS` in `dir` (exec: the shell
/// becomes fissure, so that the process waited for is fissure itself).
std::string command_line(const std::string& args, const std::filesystem::path& dir) {
  return "cd \"" + dir.string() + "\" && exec \"" + FISSURE_APP + "\" " + args + " > \"" +
         (dir / "stdout.txt").string() + "\" 2> \"" + (dir / "stderr.txt").string() + "\"";
}

std::string error_text(const std::filesystem::path& dir) {
  std::ifstream in(dir / "stderr.txt");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int run_fissure(const std::string& args, const std::filesystem::path& dir, std::string& err) {
  const int status = std::system(command_line(args, dir).c_str());
  err = error_text(dir);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run_fissure_peak(const std::string& args, const std::filesystem::path& dir, std::string& err,
                     double& peak_bytes) {
  const std::string command = command_line(args, dir);
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid) return -1;
  peak_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux: kilobytes
  err = error_text(dir);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace fissure::testing
