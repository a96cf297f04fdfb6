// The viewer's file browser (tools/m3g/viewer/FileBrowser.h): a folder's
// M3G files are found by their identifier bytes whatever their names,
// .jar archives are listed, other files are counted but not listed, and
// entries navigate the folders.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "FileBrowser.h"
#include "InputFile.h"
#include "M3GTestBytes.h"
#include "ZipTestWriter.h"

using m3gtest::Bytes;
using m3gview::BrowserEntry;
using m3gview::FileBrowser;
namespace fs = std::filesystem;

namespace {

// The JSR-184 file identifier (JSR-184 1.1, file format: 12 bytes).
const Bytes kIdentifier{0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

void write(const fs::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("m3g_browser_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// A folder as a game ships it: models named .res and .mod, a texture, notes.
void fillFolder(const fs::path& dir) {
    Bytes model = kIdentifier;
    model.insert(model.end(), 100, 0);
    write(dir / "level1.res", model);
    write(dir / "bike.mod", model);
    write(dir / "tex.png", Bytes{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 0});
    write(dir / "readme.txt", Bytes{'h', 'e', 'l', 'l', 'o', '\n'});
    write(dir / "broken.m3g", Bytes{'n', 'o', 't', ' ', 'm', '3', 'g'});  // listed by its name, reported when opened
    write(dir / ".hidden.res", model);
    m3gtest::writeZip(dir / "game.jar", {{"a.res", model}});
    m3gtest::writeZip(dir / "archive.zip", {{"a.res", model}});  // a zip not named .jar: not openable
    fs::create_directories(dir / "sub");
    write(dir / "sub" / "inner.tex", model);
}

std::vector<std::string> names(const FileBrowser& b) {
    std::vector<std::string> out;
    for (const auto& e : b.entries()) out.push_back(std::string(m3gview::kindName(e.kind)) + " " + e.name);
    return out;
}

}  // namespace

TEST(FileBrowser, ListsM3gDataByIdentifierFoldersAndJarsNothingElse) {
    TempDir dir;
    fillFolder(dir.path);
    FileBrowser b;
    b.open(dir.path);
    EXPECT_EQ(b.folder(), fs::canonical(dir.path));
    EXPECT_EQ(names(b), (std::vector<std::string>{"parent ..", "folder sub", "m3g bike.mod", "m3g broken.m3g", "jar game.jar",
                                                  "m3g level1.res"}));
    // tex.png, readme.txt and archive.zip are counted, not listed; .hidden.res is left out.
    EXPECT_EQ(b.otherFiles(), 3);
    EXPECT_EQ(b.entries()[5].size, kIdentifier.size() + 100);
}

TEST(FileBrowser, EntriesEnterFoldersAndReturnFiles) {
    TempDir dir;
    fillFolder(dir.path);
    FileBrowser b;
    b.open(dir.path);
    EXPECT_EQ(b.activate(1), "");  // sub
    EXPECT_EQ(b.folder(), fs::canonical(dir.path / "sub"));
    EXPECT_EQ(names(b), (std::vector<std::string>{"parent ..", "m3g inner.tex"}));
    EXPECT_EQ(b.activate(1), (fs::canonical(dir.path / "sub") / "inner.tex").string());
    EXPECT_EQ(b.activate(0), "");  // ..
    EXPECT_EQ(b.folder(), fs::canonical(dir.path));
    b.up();
    EXPECT_EQ(b.folder(), fs::canonical(dir.path).parent_path());
    EXPECT_THROW(b.activate(b.entries().size()), std::out_of_range);
}

TEST(FileBrowser, AMissingFolderIsAnErrorAndKeepsTheListing) {
    TempDir dir;
    fillFolder(dir.path);
    FileBrowser b;
    b.open(dir.path);
    try {
        b.open(dir.path / "nope");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("nope: no such folder"), std::string::npos) << e.what();
    }
    EXPECT_EQ(b.folder(), fs::canonical(dir.path));
    EXPECT_EQ(b.entries().size(), 6u);
}

TEST(FileBrowser, TheRootHasNoParentEntry) {
    FileBrowser b;
    b.open("/");
    ASSERT_FALSE(b.entries().empty());
    EXPECT_NE(b.entries()[0].kind, BrowserEntry::Kind::Parent);
    b.up();  // nothing above the root
    EXPECT_EQ(b.folder(), fs::path("/"));
}

TEST(InputFileSniff, SaysWhatTheBytesAreWhateverTheName) {
    TempDir dir;
    fillFolder(dir.path);
    EXPECT_TRUE(m3gcli::sniffFile(dir.path / "level1.res").m3g);
    EXPECT_TRUE(m3gcli::sniffFile(dir.path / "tex.png").image);
    EXPECT_TRUE(m3gcli::sniffFile(dir.path / "game.jar").zip);
    const m3gcli::FileContent text = m3gcli::sniffFile(dir.path / "readme.txt");
    EXPECT_FALSE(text.m3g || text.image || text.zip);
    EXPECT_EQ(text.what, "an unrecognised file");
    EXPECT_EQ(m3gcli::sniffFile(dir.path / "missing").what, "an unreadable file");
    EXPECT_TRUE(m3gcli::hasM3gName("A.M3G"));
    EXPECT_FALSE(m3gcli::hasM3gName("m3g"));
}
