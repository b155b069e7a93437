// lmc — the headless face of the workbench engine, for batch work and tests.
#include <algorithm>
#include <csignal>
#include <iostream>
#include <string>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/platform/command_line.h"

namespace lmc::cli {

std::vector<Command>& command_registry() {
  static std::vector<Command> registry;
  return registry;
}

int& command_exit_code() {
  static int code = 0;
  return code;
}

}  // namespace lmc::cli

int main(int argc, char** argv) {
  if (const std::string problem = lmc::platform::arguments_changed_by_code_page(); !problem.empty()) {
    std::cerr << "lmc: error: " << problem << "\n";
    return 2;
  }
#ifdef SIGXFSZ
  // A file-size limit (ulimit -f) must not kill the program in the middle of a trial: ignored,
  // the write fails with EFBIG and the recorder stops the trial with a clear message instead.
  std::signal(SIGXFSZ, SIG_IGN);
#endif
  CLI::App app{
      "lmc — design, record and analyse multi-Leap-Motion-Controller hand measurements.\n"
      "Every command prints its own help: lmc <command> --help"};
  app.set_version_flag("--version", std::string("lmc ") + LMC_VERSION);
  app.require_subcommand(1);
  // CLI11 on Windows would also take /name for an option, so a path such as /data/S01 would be read
  // as one; options are --name on every system. Set before the commands: they inherit it.
  app.allow_windows_style_options(false);

  auto& registry = lmc::cli::command_registry();
  std::sort(registry.begin(), registry.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  for (auto& cmd : registry) {
    CLI::App* sub = app.add_subcommand(cmd.name, cmd.summary);
    cmd.setup(*sub);
  }

  // CLI11 alone would answer "A subcommand is required" for a misspelt command: name it instead.
  if (argc < 2) {
    std::cerr << app.help();
    return 2;
  }
  if (const std::string first = argv[1]; !first.empty() && first[0] != '-') {
    const bool known = std::any_of(registry.begin(), registry.end(), [&](const auto& c) { return c.name == first; });
    if (!known) {
      std::cerr << "lmc: unknown command '" << first << "'; commands:";
      for (const auto& c : registry) std::cerr << ' ' << c.name;
      std::cerr << " (lmc --help describes each)\n";
      return 2;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const lmc::Error& e) {
    std::cerr << "lmc: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lmc: error: " << e.what() << "\n";
    return 1;
  }
  return lmc::cli::command_exit_code();
}
