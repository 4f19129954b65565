#include "tests/support/fissure_command.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fissure::testing {

int run_fissure(const std::string& args, const std::filesystem::path& dir, std::string& err) {
  const std::filesystem::path err_file = dir / "stderr.txt";
  const std::string command = "cd \"" + dir.string() + "\" && \"" + FISSURE_APP + "\" " + args +
                              " > \"" + (dir / "stdout.txt").string() + "\" 2> \"" +
                              err_file.string() + "\"";
  const int status = std::system(command.c_str());
  std::ifstream in(err_file);
  std::ostringstream s;
  s << in.rdbuf();
  err = s.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace fissure::testing
