#pragma once
// Small facts about the running process that the two systems spell differently.
namespace lmc::platform {

// This process's id, as the operating system shows it (the journal and the session lock name it).
int current_process_id();

// Whether standard error is a terminal (a progress bar is drawn only there).
bool stderr_is_terminal();

}  // namespace lmc::platform
