// OpenEXR output of the rendered radiance (float32 RGB, ZIP) with run metadata as header
// attributes, and the matching reader the tests and tools use to check what was written.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wf {

struct ExrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // row-major, top row first, 3 floats per pixel
};

// An extra float32 channel beside R, G, B (an AOV layer's, e.g. "albedo.R"): one value per
// pixel, row-major.
struct ExrChannel {
    std::string name;
    std::vector<float> values;
};

// Writes `rgb` (width * height * 3 floats, row-major, top row first) as float32 channels
// R, G, B with ZIP compression, plus the given header attributes, atomically (see
// writeFileAtomically). Attribute names must not clash with EXR's standard ones.
// Throws InputError if the folder does not exist, InternalError if writing fails or the
// arguments are inconsistent.
void writeExr(const std::string& path, int width, int height, const std::vector<float>& rgb,
              const std::vector<std::pair<std::string, std::string>>& stringAttrs = {},
              const std::vector<std::pair<std::string, float>>& floatAttrs = {},
              const std::vector<std::pair<std::string, int>>& intAttrs = {},
              const std::vector<ExrChannel>& extraChannels = {});

// One float channel of an EXR by name; nullopt if the file has no such channel. Throws
// InputError when the file cannot be read.
std::optional<std::vector<float>> readExrChannel(const std::string& path, const std::string& name);

// Reads channels R, G, B as float. Throws InputError when the file cannot be read, lacks one
// of the channels, or its data window is empty or larger than 32768 pixels per side.
ExrImage readExr(const std::string& path);

// The value of a string, int or float header attribute as text (floats with 9 significant
// digits, so they round-trip); nullopt if the attribute is absent or of another type.
// Throws InputError when the file cannot be read.
std::optional<std::string> readExrAttribute(const std::string& path, const std::string& name);
// Every string, int and float header attribute: its name, type ('s', 'i' or 'f') and value
// as readExrAttribute writes it.
struct ExrAttribute {
    std::string name;
    char type = 's';
    std::string text;
};
std::vector<ExrAttribute> readExrAttributes(const std::string& path);

} // namespace wf
