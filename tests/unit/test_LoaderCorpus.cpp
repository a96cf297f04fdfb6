// Loader over the shared corpus (../shared/corpus/models): every M3G file
// loads in strict mode except the documented ones, object counts match the
// section layer, roots are exactly the unreferenced objects.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>
#include <m3g/Loader.h>
#include <m3g/Object3D.h>

#include "FormatSniffer.h"
#include "M3GSections.h"
#include "M3GTestBytes.h"

namespace fs = std::filesystem;
using namespace m3g;

namespace {

std::string topFolder(const fs::path& models, const fs::path& file) {
    return fs::relative(file, models).begin()->string();
}

/// Every object reachable through getReferences from `o`.
void references(const Object3D* o, std::vector<Object3D*>& out) {
    const int n = o->getReferences();
    std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(n));
    o->getReferences(refs);
    for (auto& r : refs) out.push_back(r.get());
}

}  // namespace

TEST(LoaderCorpus, EveryM3GFileLoadsOrFailsAsDocumented) {
    const auto corpus = m3gtest::corpusDir();
    if (!corpus) GTEST_SKIP() << "shared corpus not found (M3G_CORPUS_DIR/models); corpus test skipped";
    const fs::path models = *corpus / "models";

    struct Counts {
        int loaded = 0, rejected = 0, notM3G = 0;
    };
    std::map<std::string, Counts> perFolder;
    int checked = 0;
    for (const auto& path : m3gtest::corpusFiles(*corpus)) {
        const auto bytes = m3gtest::readFile(path);
        const auto format = detail::sniffFormat(bytes);
        const std::string rel = fs::relative(path, models).string();
        Counts& c = perFolder[topFolder(models, path)];
        if (format != detail::InputFormat::M3G) {
            ++c.notM3G;
            if (format == detail::InputFormat::PNG) {
                // A PNG loads directly as one immutable Image2D.
                std::vector<Ref<Object3D>> roots;
                ASSERT_NO_THROW(roots = Loader::load(path.string())) << rel;
                ASSERT_EQ(roots.size(), 1u);
                auto img = dynamicCast<Image2D>(roots[0]);
                ASSERT_TRUE(img);
                EXPECT_FALSE(img->isMutable());
            }
            std::cout << "[   not M3G ] " << rel << " (" << detail::describeFormat(format) << ")\n";
            continue;
        }
        const std::string fileName = path.filename().string();
        if (fileName == "id-only.hex") {
            EXPECT_THROW(Loader::load(path.string()), IOException) << rel;
            ++c.rejected;
            std::cout << "[ rejected ] " << rel << " (identifier only: no header section, so IOException)\n";
            continue;
        }
        if (fileName == "boy.m3g") {
            try {
                Loader::load(path.string());
                ADD_FAILURE() << rel << ": loaded although its PNG is missing";
            } catch (const IOException& e) {
                const std::string m = e.what();
                EXPECT_NE(m.find(".png"), std::string::npos) << m;
                EXPECT_NE(m.find("not found"), std::string::npos) << m;
                std::cout << "[ rejected ] " << rel << ": " << m << "\n";
            }
            ++c.rejected;
            LoaderOptions lenient;
            lenient.lenient = true;
            LoadResult r;
            ASSERT_NO_THROW(r = Loader::loadDetailed(path.string(), lenient)) << rel;
            EXPECT_FALSE(r.roots.empty());
            EXPECT_FALSE(r.warnings.empty());
            for (const auto& w : r.warnings) std::cout << "  lenient warning: " << w << "\n";
            continue;
        }

        LoadResult r;
        try {
            r = Loader::loadDetailed(path.string());
        } catch (const Exception& e) {
            ADD_FAILURE() << rel << ": " << e.what();
            ++c.rejected;
            continue;
        }
        ++c.loaded;
        ++checked;
        EXPECT_TRUE(r.warnings.empty()) << rel;

        // Object count: every record after the header gives one object
        // (an external reference gives the object it loaded).
        detail::LoadLog log;
        const auto file = detail::parseM3GFile(bytes, log);
        EXPECT_EQ(r.objects.size(), file.objects.size() - 1) << rel;
        EXPECT_EQ(r.versionMajor, 1);
        EXPECT_EQ(r.versionMinor, 0);
        EXPECT_EQ(r.totalFileSize, file.header.totalFileSize);
        EXPECT_EQ(r.authoringField, file.header.authoringField);

        // Roots = the objects no other loaded object refers to, file order.
        std::set<const Object3D*> referenced;
        std::set<const Object3D*> loaded;
        for (const auto& o : r.objects) loaded.insert(o.get());
        for (const auto& o : r.objects) {
            std::vector<Object3D*> refs;
            references(o.get(), refs);
            for (auto* x : refs)
                if (x != o.get()) referenced.insert(x);
        }
        std::vector<Object3D*> expectedRoots;
        for (const auto& o : r.objects)
            if (!referenced.count(o.get())) expectedRoots.push_back(o.get());
        std::vector<Object3D*> roots;
        for (const auto& o : r.roots) roots.push_back(o.get());
        EXPECT_EQ(roots, expectedRoots) << rel;
        // A lenient load of a valid file gives the same objects and no warning.
        LoaderOptions lenientOptions;
        lenientOptions.lenient = true;
        const auto lr = Loader::loadDetailed(path.string(), lenientOptions);
        EXPECT_EQ(lr.objects.size(), r.objects.size()) << rel;
        EXPECT_EQ(lr.roots.size(), r.roots.size()) << rel;
        EXPECT_TRUE(lr.warnings.empty()) << rel;
        std::cout << "[   loaded ] " << rel << ": " << r.objects.size() << " objects, " << r.roots.size() << " roots"
                  << (r.hasExternalReferences ? ", with external references" : "") << "\n";
    }
    for (const auto& [folder, c] : perFolder)
        std::cout << "[  summary ] " << folder << ": " << c.loaded << " loaded, " << c.rejected << " rejected, "
                  << c.notM3G << " not M3G (skipped)\n";
    EXPECT_GT(checked, 0);
}
