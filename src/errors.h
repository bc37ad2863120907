// The three ways a run ends badly, mapped to exit codes by main(): bad usage or bad input
// (2, one clear line), anything else (1).
#pragma once
#include <stdexcept>
#include <string>

namespace wf {

// The user's input (flags, scene file, image file) is wrong: exit code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The command line is wrong: exit code 2, with a hint to run --help.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Vulkan, the shader compiler or the file system failed: exit code 1.
class InternalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace wf
