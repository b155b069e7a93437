#pragma once
// Every `lmc` subcommand registers itself from its own file in app/lmc/commands/, so adding a
// command never touches a shared list:
//   static const lmc::cli::CommandRegistration reg{"info", "Describe a recording, TRC or layout", 10, setup_info};
// `setup` adds options to the subcommand and sets its callback; callbacks throw lmc::Error (or
// any std::exception) on failure and main turns that into a message on stderr and exit code 1.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace lmc::cli {

struct Command {
  std::string name;
  std::string summary;
  int order;  // position in `lmc --help`
  std::function<void(CLI::App&)> setup;
};

std::vector<Command>& command_registry();

struct CommandRegistration {
  CommandRegistration(std::string name, std::string summary, int order, std::function<void(CLI::App&)> setup) {
    command_registry().push_back({std::move(name), std::move(summary), order, std::move(setup)});
  }
};

// Exit code a command callback may set for "ran, but found problems" (e.g. some trials failed).
int& command_exit_code();

}  // namespace lmc::cli
