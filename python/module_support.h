// What the module's C++ files share: the exceptions that become wavefront.DeviceError,
// ClosedError and ImageError (ImageFileError; wf::InputError becomes SceneError, wf::UsageError ValueError,
// wf::InternalError wavefront.Error), and where the shaders are.
#pragma once
#include <stdexcept>
#include <string>

namespace wf::py {

struct DeviceError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
struct ClosedError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
struct ImageFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// WAVEFRONT_SHADER_DIR, else the installed package's shaders/, else the CLI's default (the
// source tree this module was built from).
std::string moduleShaderDir();
void setPackageDir(const std::string& dir);

} // namespace wf::py
