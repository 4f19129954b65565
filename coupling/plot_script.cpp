#include "coupling/plot_script.h"

#include <cstdlib>
#include <filesystem>

namespace fissure {

bool run_plot_script(const std::string& script, const std::string& outdir) {
  const std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command =
      python + " " + FISSURE_SCRIPTS_DIR + "/" + script + " '" + outdir + "' > /dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

}  // namespace fissure
