#include "parse_errors.h"

#include <algorithm>
#include <iostream>

namespace woven {

namespace {

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string joined(const std::vector<std::string>& names) {
    std::string list;
    for (size_t i = 0; i < names.size(); ++i) list += (i ? (i + 1 == names.size() ? " or " : ", ") : "") + names[i];
    return list;
}

std::vector<std::string> commandNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> optionNames(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

// "woven render": the command the error is about (the root's name is argv[0], a path).
std::string commandPath(const CLI::App* app) {
    std::string path;
    for (; app && app->get_parent(); app = app->get_parent()) path = app->get_name() + (path.empty() ? "" : " " + path);
    return "woven " + path;
}

std::string valueCountMessage(const std::string& message) {
    const size_t colon = message.find(": ");
    if (colon == std::string::npos) return message;
    const std::string option = message.substr(0, colon), rest = message.substr(colon + 2);
    const auto count = [&](const std::string& before) -> std::string {
        const size_t at = rest.find(before);
        if (at == std::string::npos) return "";
        const size_t start = at + before.size();
        return rest.substr(start, rest.find_first_not_of("0123456789", start) - start);
    };
    const auto values = [](const std::string& n) { return n == "1" ? std::string("one value") : n + " values"; };
    if (rest.rfind("At Most ", 0) == 0)
        return option + ": takes " + values(count("At Most ")) + ", given " + count("received ") + " (give the option once)";
    if (rest.rfind("At least ", 0) == 0)
        return option + ": takes " + values(count("At least ")) + ", given " + count("received ");
    if (rest.find(" missing") != std::string::npos) return option + ": a value is missing";
    return message;
}

}  // namespace

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t bestDistance = std::max<size_t>(1, (word.size() + 2) / 3) + 1;  // a third of the letters, rounded up
    for (const std::string& candidate : candidates) {
        const size_t d = editDistance(word, candidate);
        if (d < bestDistance) best = candidate, bestDistance = d;
    }
    return best;
}

int reportParseError(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
    const int code = error.get_exit_code();
    if (dynamic_cast<const CLI::CallForHelp*>(&error) || dynamic_cast<const CLI::CallForAllHelp*>(&error) ||
        dynamic_cast<const CLI::Success*>(&error))
        return app.exit(error);
    // A command that already said what went wrong and only sets the exit code.
    if (dynamic_cast<const CLI::RuntimeError*>(&error)) return code;
    const auto parsed = app.get_subcommands();
    if (parsed.empty()) {
        const std::vector<std::string> commands = commandNames(app);
        std::string first;
        for (int i = 1; i < argc && first.empty(); ++i)
            if (argv[i][0] != '-') first = argv[i];
        if (first.empty()) {
            std::cerr << "woven: error: a command is needed: " << joined(commands) << " (woven --help says what each does)\n";
            return code;
        }
        const std::string meant = closestName(first, commands);
        std::cerr << "woven: error: '" << first << "' is not a woven command"
                  << (meant.empty() ? ": the commands are " + joined(commands) : "; did you mean '" + meant + "'?")
                  << " (woven --help)\n";
        return code;
    }
    const CLI::App& command = *parsed.back();
    const std::string name = commandPath(&command);
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        const std::vector<std::string> extras = command.remaining();
        // The value after an unknown option is no argument of its own: name the option alone.
        const bool anyOption = std::any_of(extras.begin(), extras.end(), [](const std::string& e) { return e.rfind('-', 0) == 0; });
        for (const std::string& extra : extras) {
            if (extra.rfind('-', 0) != 0) {
                if (!anyOption) std::cerr << name << ": error: unexpected argument '" << extra << "'\n";
                continue;
            }
            const std::string option = extra.substr(0, extra.find('='));
            const std::string meant = closestName(option, optionNames(command));
            std::cerr << name << ": error: unknown option '" << option << "'"
                      << (meant.empty() ? "" : "; did you mean '" + meant + "'?") << "\n";
        }
        std::cerr << "(" << name << " --help lists its options)\n";
        return code;
    }
    std::string message = error.what();
    // CLI11's "Could not convert: --first-sample = 4294967295": the value does not fit the option.
    const std::string unconverted = "Could not convert: ";
    if (dynamic_cast<const CLI::ConversionError*>(&error) && message.rfind(unconverted, 0) == 0) {
        const std::string rest = message.substr(unconverted.size());
        const size_t eq = rest.find(" = ");
        if (eq != std::string::npos)
            message = rest.substr(0, eq) + ": '" + rest.substr(eq + 3) + "' is not a value this option takes (a whole number "
                      "in its range, or a number where it takes one)";
    }
    // CLI11's counts of values ("--width: At Most 1 required but received 2", "--size: At least 2
    // required but received 1", "--budgets: 1 required FLOAT:... missing") in woven's words.
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) message = valueCountMessage(message);
    // CLI11's "--spp excludes --list": either may come first.
    if (const size_t at = message.find(" excludes "); dynamic_cast<const CLI::ExcludesError*>(&error) && at != std::string::npos)
        message = message.substr(0, at) + " and " + message.substr(at + 10) + " cannot be given together";
    std::cerr << name << ": error: " << message << "\n(" << name << " --help lists its options)\n";
    return code;
}

}  // namespace woven
