#include "app/cli.h"

#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "errors.h"

namespace wf {

std::vector<OptionSpec> joinOptions(std::initializer_list<std::vector<OptionSpec>> groups) {
    std::vector<OptionSpec> options;
    for (const std::vector<OptionSpec>& group : groups)
        options.insert(options.end(), group.begin(), group.end());
    return options;
}

std::optional<std::string> ParsedArgs::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end())
        return std::nullopt;
    return it->second;
}

uint32_t ParsedArgs::uintValue(const std::string& name, uint32_t fallback, uint32_t minValue,
                               uint32_t maxValue) const {
    auto text = value(name);
    if (!text)
        return fallback;
    const char* begin = text->c_str();
    char* end = nullptr;
    errno = 0;
    unsigned long long parsed = std::strtoull(begin, &end, 10);
    bool digitsOnly = !text->empty() && text->find_first_not_of("0123456789") == std::string::npos;
    if (!digitsOnly || *end != '\0' || errno == ERANGE || parsed < minValue || parsed > maxValue)
        throw UsageError(name + " expects an integer from " + std::to_string(minValue) + " to " +
                         std::to_string(maxValue) + ", got '" + *text + "'");
    return static_cast<uint32_t>(parsed);
}

float ParsedArgs::floatValue(const std::string& name, float fallback, float minValue,
                             float maxValue) const {
    auto text = value(name);
    if (!text)
        return fallback;
    char* end = nullptr;
    errno = 0;
    float parsed = std::strtof(text->c_str(), &end);
    if (text->empty() || *end != '\0' || errno == ERANGE || !std::isfinite(parsed) ||
        parsed < minValue || parsed > maxValue) {
        std::ostringstream message;
        message << name << " expects a number from " << minValue << " to " << maxValue
                << ", got '" << *text << "'";
        throw UsageError(message.str());
    }
    return parsed;
}

std::string ParsedArgs::choiceValue(const std::string& name, const std::string& fallback,
                                    const std::vector<std::string>& choices) const {
    auto text = value(name);
    if (!text)
        return fallback;
    std::string list;
    for (const auto& choice : choices) {
        if (*text == choice)
            return choice;
        list += (list.empty() ? "" : ", ") + choice;
    }
    throw UsageError(name + " expects one of " + list + ", got '" + *text + "'");
}

ParsedArgs parseArgs(const CommandSpec& spec, const std::vector<std::string>& args) {
    ParsedArgs parsed;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--help" || arg == "-h") {
            parsed.set("--help", "");
            continue;
        }
        if (arg.size() < 2 || arg[0] != '-') {
            parsed.positional.push_back(arg);
            continue;
        }
        std::string name = arg, inlineValue;
        bool hasInline = false;
        if (auto eq = arg.find('='); eq != std::string::npos && arg.rfind("--", 0) == 0) {
            name = arg.substr(0, eq);
            inlineValue = arg.substr(eq + 1);
            hasInline = true;
        }
        const OptionSpec* option = nullptr;
        for (const auto& candidate : spec.options)
            if (candidate.name == name || (!candidate.shortName.empty() &&
                                           candidate.shortName == name))
                option = &candidate;
        if (!option)
            throw UsageError("unknown option '" + name + "' for 'wavefront " + spec.name +
                             "' (see wavefront " + spec.name + " --help)");
        if (option->valueName.empty()) {
            if (hasInline)
                throw UsageError(option->name + " takes no value");
            parsed.set(option->name, "");
        } else if (hasInline) {
            parsed.set(option->name, inlineValue);
        } else {
            if (i + 1 >= args.size())
                throw UsageError(option->name + " needs a value (" + option->valueName + ")");
            parsed.set(option->name, args[++i]);
        }
    }
    return parsed;
}

std::optional<ParsedArgs> parseSceneCommand(const CommandSpec& spec,
                                            const std::vector<std::string>& args) {
    ParsedArgs parsed = parseArgs(spec, args);
    if (parsed.has("--help")) {
        std::fputs(helpText(spec).c_str(), stdout);
        return std::nullopt;
    }
    if (parsed.positional.size() != 1)
        throw UsageError(spec.name + " needs exactly one scene file (see wavefront " + spec.name +
                         " --help)");
    return parsed;
}

std::string helpText(const CommandSpec& spec) {
    std::ostringstream out;
    out << "Usage: " << spec.usage << "\n\n" << spec.summary << "\n\nOptions:\n";
    for (const auto& option : spec.options) {
        std::string flag = option.shortName.empty() ? "    " : option.shortName + ", ";
        flag += option.name;
        if (!option.valueName.empty())
            flag += " " + option.valueName;
        out << "  " << flag;
        out << std::string(flag.size() < 26 ? 26 - flag.size() : 1, ' ') << option.description
            << "\n";
    }
    out << "  -h, --help                  show this help\n";
    if (!spec.epilogue.empty())
        out << "\n" << spec.epilogue;
    return out.str();
}

} // namespace wf
