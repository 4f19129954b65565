#include "coupling/plot_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace fissure {

namespace {

/// `text` as one word for the shell: in single quotes, each ' as '\''.
std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

bool run_plot_script(const std::string& script, const std::string& outdir) {
  const std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " " + shell_quoted(FISSURE_SCRIPTS_DIR "/" + script) + " " +
                              shell_quoted(outdir) + " > /dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

void draw_run_pictures(const std::string& outdir) {
  struct Picture {
    const char* script;
    const char* png;
  };
  const Picture pictures[] = {{"plot_monitors.py", "monitors.png"},
                              {"plot_final_state.py", "final_state.png"}};
  // A picture left by an earlier run in this folder would pass for this one's.
  for (const Picture& p : pictures) {
    std::error_code ignored;
    std::filesystem::remove(std::filesystem::path(outdir) / p.png, ignored);
  }
  // Both in one python process (scripts/plot_run.py: matplotlib imported
  // once). The scripts exit normally without a picture when there is nothing
  // to draw (no monitors, no frame): only the files tell.
  run_plot_script("plot_run.py", outdir);
  for (const Picture& p : pictures) {
    const std::filesystem::path png = std::filesystem::path(outdir) / p.png;
    if (std::filesystem::exists(png))
      std::printf("  picture: %s\n", png.string().c_str());
    else
      std::printf(
          "  picture: %s not made (nothing to draw, or python3 lacks h5py or matplotlib; "
          "scripts/%s %s says which)\n",
          p.png, p.script, outdir.c_str());
  }
}

}  // namespace fissure
