// Subcommand entry points. Each returns the process exit code or throws (see errors.h).
#pragma once
#include <string>
#include <vector>

namespace wf {

int runRenderCommand(const std::vector<std::string>& args);
std::string renderHelp();

} // namespace wf
