#include "CliApp.h"

#include <cstdio>
#include <memory>
#include <new>

#include <m3g/Version.h>
#include <m3g/vk/Vulkan.h>

#include "Suggest.h"

namespace m3gcli {

namespace {

/// The root and the commands selected on the command line, outermost first
/// (filled in as CLI11 meets them, so also after a parse error).
std::vector<CLI::App*> selectedChain(CLI::App& root) {
    std::vector<CLI::App*> chain{&root};
    for (CLI::App* app = &root;;) {
        const auto selected = app->get_subcommands();
        if (selected.empty()) return chain;
        app = selected.front();
        chain.push_back(app);
    }
}

/// "m3g bench render" for that chain.
std::string chainName(const std::vector<CLI::App*>& chain) {
    std::string name;
    for (const CLI::App* app : chain) name += (name.empty() ? "" : " ") + app->get_name();
    return name;
}

std::vector<CLI::App*> commandsOf(CLI::App& app) {
    return app.get_subcommands([](CLI::App*) { return true; });
}

std::vector<std::string> optionNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options()) {
        for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : o->get_snames()) names.push_back("-" + s);
    }
    return names;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates) {
    const auto best = closestName(word, candidates);
    return best ? "; did you mean '" + *best + "'?" : "";
}

/// A command-line word CLI11 left over that reads as an option (not "-",
/// not a negative number, which CLI11 takes as an operand too).
bool looksLikeOption(const std::string& s) {
    return s.size() > 1 && s[0] == '-' && !(s[1] >= '0' && s[1] <= '9') && s[1] != '.';
}

/// The message of a parse error. A word CLI11 could not place is named
/// first, whatever error CLI11 stopped at: a mistyped option is why a
/// required operand then seems missing.
std::string describeParseError(CLI::App& root, const CLI::ParseError& e) {
    const std::vector<CLI::App*> chain = selectedChain(root);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
        for (const std::string& word : (*it)->remaining())
            if (looksLikeOption(word)) {
                const std::string name = word.starts_with("--") ? word.substr(0, word.find('=')) : word;
                return "unknown option '" + name + "'" + didYouMean(name, optionNames(**it));
            }
    CLI::App& leaf = *chain.back();
    const auto left = leaf.remaining();
    if (!left.empty()) {
        const auto commands = commandsOf(leaf);
        if (commands.empty()) return "unexpected argument '" + left.front() + "'";
        std::vector<std::string> names;
        for (const CLI::App* c : commands) names.push_back(c->get_name());
        return "unknown command '" + left.front() + "'" + didYouMean(left.front(), names);
    }
    // "b is required": an operand is known by its placeholder and meaning,
    // as the usage shows it ("missing B.png (the second image...)").
    const std::string what = e.what();
    const std::string required = " is required";
    if (what.ends_with(required)) {
        const CLI::Option* o = leaf.get_option_no_throw(what.substr(0, what.size() - required.size()));
        if (o && o->get_positional())
            return "missing " + o->get_type_name() + " (" + o->get_description() + ")";
    }
    return what;
}

/// The usage of `app` alone (CLI11's help() would go on to a selected
/// subcommand: for `m3g help`, that is `help` itself).
std::string helpOf(const CLI::App& app, const std::string& path) {
    return app.get_formatter()->make_help(&app, path, CLI::AppFormatMode::Normal);
}

std::string versionLine() { return std::string("m3g-vk ") + m3g::kVersionString; }

}  // namespace

std::string exitCodesText() {
    return "Exit codes:\n"
           "  0  success\n"
           "  1  a check said no: compare or render --reference over the limits, bench soak's verdict,\n"
           "     a view --script expect-pick\n"
           "  2  usage error: unknown command or option, missing or bad value\n"
           "  3  an input cannot be read or loaded (missing, a directory, malformed)\n"
           "  4  an output cannot be written\n"
           "  5  no Vulkan device or display, or rendering failed\n";
}

CLI::App* addCommandApp(CLI::App& parent, const std::string& name, const std::string& description) {
    CLI::App* app = parent.add_subcommand(name, description);
    app->footer(exitCodesText());
    // At most one: a later command name is an operand or an error, never a
    // second command run after the first.
    app->require_subcommand(0, 1);
    return app;
}

void configureRoot(CLI::App& root) {
    root.name("m3g");
    root.description("m3g-vk " + std::string(m3g::kVersionString) +
                     ": the M3G (JSR-184) tool. `m3g COMMAND --help` or `m3g help COMMAND` describes a command.");
    root.footer(exitCodesText());
    root.require_subcommand(0, 1);
    root.get_formatter()->column_width(36);
    root.set_version_flag("--version", versionLine(), "print the version and exit");
}

void addHelpCommands(CLI::App& root, CommandTable& table) {
    CLI::App* help = addCommandApp(root, "help", "print the usage of m3g or of a command: help render, help bench soak");
    auto words = std::make_shared<std::vector<std::string>>();
    help->add_option("command", *words, "the command (and subcommand) to describe")->type_name("COMMAND...");
    table[help] = [&root, words] {
        CLI::App* app = &root;
        std::string path;
        for (const std::string& w : *words) {
            CLI::App* next = nullptr;
            std::vector<std::string> names;
            for (CLI::App* c : commandsOf(*app)) {
                names.push_back(c->get_name());
                if (c->get_name() == w) next = c;
            }
            if (!next) throw CliError("unknown command '" + w + "'" + didYouMean(w, names));
            path += (path.empty() ? "" : " ") + app->get_name();
            app = next;
        }
        std::printf("%s", helpOf(*app, path.empty() && app == &root ? "m3g" : path + " " + app->get_name()).c_str());
        return int(kExitOk);
    };

    CLI::App* version = addCommandApp(root, "version", "print the version (as --version)");
    table[version] = [] {
        std::printf("%s\n", versionLine().c_str());
        return int(kExitOk);
    };
}

void parseArgs(CLI::App& app, const std::vector<std::string>& args) {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        throw;
    } catch (const CLI::CallForAllHelp&) {
        throw;
    } catch (const CLI::CallForVersion&) {
        throw;
    } catch (const CLI::ParseError& e) {
        throw CliError(describeParseError(app, e));
    }
}

int reportFailure(const std::string& where) {
    auto print = [&](const char* what) { std::fprintf(stderr, "%s: %s\n", where.c_str(), what); };
    try {
        throw;
    } catch (const CliError& e) {
        print(e.what());
        std::fprintf(stderr, "Run '%s --help' for the options.\n", where.c_str());
        return kExitUsage;
    } catch (const InputError& e) {
        print(e.what());
        return kExitInput;
    } catch (const OutputError& e) {
        print(e.what());
        return kExitOutput;
    } catch (const RenderError& e) {
        print(e.what());
        return kExitRender;
    } catch (const m3g::vk::VulkanError& e) {
        print(e.what());
        return kExitRender;
    } catch (const std::bad_alloc&) {
        print("out of memory");
        return kExitRender;
    } catch (const std::exception& e) {
        print(e.what());
        return kExitRender;
    }
}

int runCommandLine(CLI::App& root, const CommandTable& table, const std::vector<std::string>& args) {
    try {
        parseArgs(root, args);
    } catch (const CLI::CallForHelp&) {
        std::printf("%s", root.help().c_str());  // the selected command's
        return kExitOk;
    } catch (const CLI::CallForAllHelp&) {
        std::printf("%s", root.help("", CLI::AppFormatMode::All).c_str());
        return kExitOk;
    } catch (const CLI::CallForVersion& e) {
        std::printf("%s\n", e.what());
        return kExitOk;
    } catch (...) {
        return reportFailure(chainName(selectedChain(root)));
    }
    const std::vector<CLI::App*> chain = selectedChain(root);
    const std::string where = chainName(chain);
    CLI::App& leaf = *chain.back();
    const auto run = table.find(&leaf);
    if (run == table.end()) {
        // The root or a group of commands (bench) without its command.
        std::string names;
        for (const CLI::App* c : commandsOf(leaf)) names += (names.empty() ? "" : ", ") + c->get_name();
        std::fprintf(stderr, "%s", helpOf(leaf, where).c_str());
        std::fprintf(stderr, "%s: needs a command: %s\n", where.c_str(), names.c_str());
        return kExitUsage;
    }
    try {
        return run->second();
    } catch (...) {
        return reportFailure(where);
    }
}

int runOneCommand(CommandAdder add, const std::string& name, std::span<const std::string_view> args) {
    CLI::App root;
    CommandTable table;
    configureRoot(root);
    add(root, table);
    addHelpCommands(root, table);
    std::vector<std::string> words{name};
    for (std::string_view a : args) words.emplace_back(a);
    return runCommandLine(root, table, words);
}

}  // namespace m3gcli
