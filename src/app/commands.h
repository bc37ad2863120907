// Subcommand entry points. Each returns the process exit code or throws (see errors.h).
#pragma once
#include <string>
#include <vector>

namespace wf {

int runRenderCommand(const std::vector<std::string>& args);
std::string renderHelp();
int runConvergeCommand(const std::vector<std::string>& args);
std::string convergeHelp();
int runBenchCommand(const std::vector<std::string>& args);
std::string benchHelp();
int runMergeCommand(const std::vector<std::string>& args);
std::string mergeHelp();
// Only in builds with the viewer (WF_BUILD_VIEWER, defines WF_HAVE_VIEWER).
int runViewCommand(const std::vector<std::string>& args);
std::string viewHelp();

} // namespace wf
