// A small declarative command-line parser: each subcommand lists its options once, and the
// same table drives parsing, validation and --help, so help can never miss a flag.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace wf {

struct OptionSpec {
    std::string name;        // "--spp"
    std::string shortName;   // "-o" or empty
    std::string valueName;   // "N"; empty for a switch
    std::string description; // one line, including the default
};

struct CommandSpec {
    std::string name;       // "render"
    std::string usage;      // "wavefront render SCENE.gltf -o OUT.exr [options]"
    std::string summary;    // one line
    std::vector<OptionSpec> options;
    std::string epilogue;   // extra text after the option list (environment, exit codes)
};

// The groups of options in order, as one list (a command's own options and shared groups, e.g.
// those of app/render_options.h).
std::vector<OptionSpec> joinOptions(std::initializer_list<std::vector<OptionSpec>> groups);

class ParsedArgs {
public:
    std::vector<std::string> positional;
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    // Unsigned integer in [minValue, maxValue]; UsageError names the flag otherwise.
    uint32_t uintValue(const std::string& name, uint32_t fallback, uint32_t minValue,
                       uint32_t maxValue) const;
    // Finite number in [minValue, maxValue].
    float floatValue(const std::string& name, float fallback, float minValue,
                     float maxValue) const;
    // One of `choices`; UsageError lists them otherwise.
    std::string choiceValue(const std::string& name, const std::string& fallback,
                            const std::vector<std::string>& choices) const;
    void set(const std::string& name, std::string value) { values_[name] = std::move(value); }

private:
    std::map<std::string, std::string> values_;
};

// Throws UsageError on an unknown flag or a missing value. "--help"/"-h" are always accepted.
ParsedArgs parseArgs(const CommandSpec& spec, const std::vector<std::string>& args);
std::string helpText(const CommandSpec& spec);

// The start every scene command shares: parses, prints help and returns nullopt for --help,
// and insists on exactly one scene file.
std::optional<ParsedArgs> parseSceneCommand(const CommandSpec& spec,
                                            const std::vector<std::string>& args);

} // namespace wf
