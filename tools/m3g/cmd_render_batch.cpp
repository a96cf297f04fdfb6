// Batch mode of m3g render: every M3G file of a folder or of a J2ME .jar
// (found by its identifier bytes, whatever its name), with a progress bar on
// a terminal and a summary of what failed and why and of what was skipped.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliErrors.h"
#include "InputFile.h"
#include "JarArchive.h"
#include "RenderRun.h"

namespace m3gcli {

namespace fs = std::filesystem;

namespace {

struct BatchItem {
    std::string label;   ///< path shown in the progress bar and summary
    fs::path relative;   ///< output path under OUTDIR, before ".png"
    std::function<m3g::LoadResult(const m3g::LoaderOptions&)> load;
};

/// Where a model's images go under OUTDIR: "level.m3g" -> "level", but
/// "level.res" -> "level.res", so that level.m3g and level.res beside it
/// do not write the same PNG.
fs::path outputStem(const fs::path& relative) {
    return hasM3gName(relative.filename().string()) ? fs::path(relative).replace_extension() : relative;
}

/// One line redrawn in place on a terminal: [#####-----] 12/40 name.
class ProgressBar {
public:
    explicit ProgressBar(int total) : total_(total), enabled_(isatty(fileno(stderr)) != 0) {}
    void show(int done, const std::string& label) {
        if (!enabled_) return;
        constexpr int kWidth = 30;
        const int filled = total_ > 0 ? kWidth * done / total_ : kWidth;
        std::string name = label;
        if (name.size() > 40) name = "..." + name.substr(name.size() - 37);
        std::fprintf(stderr, "\r[%s%s] %d/%d %-40s", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                     std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(), done, total_, name.c_str());
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_) std::fprintf(stderr, "\r%*s\r", 90, "");
    }

private:
    int total_;
    bool enabled_;
};

/// The folder's M3G files: those that begin with the JSR-184 identifier,
/// whatever their name (games ship models as .res, .mod, .tex...), and those
/// named .m3g (reported if broken). The other files go to `skipped`, each
/// with what its bytes are.
std::vector<BatchItem> folderItems(const fs::path& dir, std::vector<std::string>& skipped) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied)) {
        if (!e.is_regular_file()) continue;
        const FileContent content = sniffFile(e.path());
        if (listedAsM3g(content, e.path().filename().string()))
            files.push_back(e.path());
        else
            skipped.push_back(fs::relative(e.path(), dir).string() + " (" + content.what + ")");
    }
    std::sort(files.begin(), files.end());
    std::sort(skipped.begin(), skipped.end());
    std::vector<BatchItem> items;
    for (const fs::path& f : files) {
        BatchItem item;
        item.label = f.string();
        item.relative = outputStem(fs::relative(f, dir));
        item.load = [f](const m3g::LoaderOptions& options) { return m3g::Loader::loadDetailed(f.string(), options); };
        items.push_back(std::move(item));
    }
    return items;
}

std::vector<BatchItem> jarItems(const std::shared_ptr<JarArchive>& jar, std::vector<std::string>& skipped) {
    std::vector<BatchItem> items;
    for (const std::string& name : jar->m3gEntries(&skipped)) {
        BatchItem item;
        item.label = jar->path() + "!/" + name;
        // Entry names that leave the folder fail in load() before this is used.
        item.relative = outputStem(fs::path(name));
        item.load = [jar, name](const m3g::LoaderOptions& options) { return jar->load(name, options); };
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace

int renderBatch(const RenderOptions& o) {
    std::vector<BatchItem> items;
    std::vector<std::string> skipped;
    std::shared_ptr<JarArchive> jar;
    try {
        if (fs::is_directory(o.input)) {
            items = folderItems(o.input, skipped);
        } else {
            jar = std::make_shared<JarArchive>(o.input);
            items = jarItems(jar, skipped);
        }
    } catch (const std::exception& e) {
        throw InputError(withPath(o.input, e.what()));
    }
    if (items.empty())
        throw InputError("no M3G data in " + o.input + " (" + std::to_string(skipped.size()) +
                         " file(s), none beginning with the JSR-184 identifier)");
    m3g::LoaderOptions options;
    options.lenient = o.lenient;
    struct Failure {
        std::string label, reason;
        int code;  ///< the exit code this failure alone would give
    };
    std::vector<Failure> failures;
    int warned = 0;
    ProgressBar bar(static_cast<int>(items.size()));
    for (std::size_t i = 0; i < items.size(); ++i) {
        const BatchItem& item = items[i];
        bar.show(static_cast<int>(i), item.label);
        try {
            const m3g::LoadResult loaded = item.load(options);
            if (!loaded.warnings.empty()) ++warned;
            fs::path out = fs::path(o.output) / item.relative;
            out += o.sequence() ? "_{frame}.png" : ".png";
            renderToFiles(loaded, o, out.string(), nullptr);
        } catch (const m3g::vk::VulkanError& e) {
            bar.finish();
            // No device: every further file would fail the same way.
            throw RenderError(std::string(e.what()) + " (batch stopped at " + item.label + ")");
        } catch (const std::exception& e) {
            // Loader messages start with the file's name, once or twice.
            std::string reason = withPath(item.label, e.what()).substr(item.label.size() + 2);
            const int code = dynamic_cast<const CliError*>(&e)      ? kExitUsage
                             : dynamic_cast<const OutputError*>(&e) ? kExitOutput
                             : dynamic_cast<const RenderError*>(&e) ? kExitRender
                                                                    : kExitInput;
            failures.push_back({item.label, reason, code});
        }
    }
    bar.show(static_cast<int>(items.size()), "");
    bar.finish();
    const std::size_t ok = items.size() - failures.size();
    std::printf("rendered %zu file(s) from %s into %s: %zu ok, %zu failed", items.size(), o.input.c_str(),
                o.output.c_str(), ok, failures.size());
    if (warned) std::printf(" (%d with lenient-mode warnings)", warned);
    std::printf("\n");
    for (const Failure& f : failures) std::printf("  failed: %s: %s\n", f.label.c_str(), f.reason.c_str());
    if (!skipped.empty()) {
        // Named so that a model under an unusual name is never missed silently.
        constexpr std::size_t kListed = 10;
        std::printf("skipped %zu file(s) that are not M3G data (by their first bytes):", skipped.size());
        for (std::size_t i = 0; i < std::min(kListed, skipped.size()); ++i)
            std::printf("%s %s", i ? "," : "", skipped[i].c_str());
        if (skipped.size() > kListed) std::printf(", and %zu more", skipped.size() - kListed);
        std::printf("\n");
    }
    // The first failure's code: the one a user fixes first.
    return failures.empty() ? int(kExitOk) : failures.front().code;
}

}  // namespace m3gcli
