// JarArchive (tools/m3g/): listing, reading, corrupt input and loading .m3g
// entries whose external references point at other entries. The archives
// are written here with minizip's zip writer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <png.h>

#include <m3g/m3g.h>

#include "JarArchive.h"
#include "M3GTestBytes.h"
#include "SampleScene.h"
#include "ZipTestWriter.h"

using namespace m3g;
using m3gcli::JarArchive;
using m3gcli::JarError;
using m3gtest::Bytes;
using m3gtest::writeZip;
namespace fs = std::filesystem;

namespace {

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

Bytes pngBytes(int w, int h) {
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    img.width = static_cast<png_uint_32>(w);
    img.height = static_cast<png_uint_32>(h);
    img.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h * 3), 0x40);
    png_alloc_size_t size = 0;
    png_image_write_to_memory(&img, nullptr, &size, 0, px.data(), 0, nullptr);
    Bytes out(size);
    png_image_write_to_memory(&img, out.data(), &size, 0, px.data(), 0, nullptr);
    out.resize(size);
    return out;
}

/// An .m3g file holding only an External Reference to `uri` (its root is the
/// referenced object).
Bytes externalOnly(const std::string& uri) {
    m3gtest::FileSpec f;
    f.hasExt = 1;
    m3gtest::Writer w;
    w.str(uri);
    f.sections.push_back({0, {m3gtest::object(255, w.b)}});
    return f.build();
}

Bytes sampleSceneBytes(const fs::path& dir) {
    Ref<World> world = m3gcli::buildSampleScene();
    Object3D* roots[] = {world.get()};
    Saver::save((dir / "sample.m3g").string(), roots);
    return m3gtest::readFile(dir / "sample.m3g");
}

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("m3g_jar_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no exception)";
}

}  // namespace

TEST(JarArchive, M3gEntriesAreFoundByTheirIdentifierWhateverTheName) {
    // The JSR-184 file identifier (JSR-184 1.1, file format: 12 bytes), then
    // anything: the entry is listed as M3G data even named .res or .bin.
    const Bytes identifier{0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
    Bytes model = identifier;
    model.insert(model.end(), 100, 0);
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"a.png", Bytes{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A}},
                   {"res/car.res", model},
                   {"res/empty.bin", {}},
                   {"res/road.BIN", model, false},
                   {"res/nearly.bin", Bytes(identifier.begin(), identifier.begin() + 11)}});  // a prefix
    JarArchive a(jar.string());
    std::vector<std::string> others;
    // A prefix of the identifier counts as M3G (a truncated model, which a
    // batch then reports as failed rather than skipping it).
    EXPECT_EQ(a.m3gEntries(&others), (std::vector<std::string>{"res/car.res", "res/road.BIN", "res/nearly.bin"}));
    EXPECT_EQ(others, (std::vector<std::string>{"a.png", "res/empty.bin"}));
    EXPECT_EQ(a.m3gEntries().size(), 3u) << "others is optional";
}

TEST(JarArchive, ListsFileEntriesInOrderWithoutFolders) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"META-INF/MANIFEST.MF", text("Manifest-Version: 1.0\n")},
                   {"res/", {}},
                   {"res/hero.M3G", text("not really m3g"), false},
                   {"Game.class", Bytes(300, 0xCA)},
                   {"res/level1.m3g", Bytes(5000, 7)}});
    JarArchive a(jar.string());
    ASSERT_EQ(a.entries().size(), 4u);
    EXPECT_EQ(a.entries()[0].name, "META-INF/MANIFEST.MF");
    EXPECT_EQ(a.entries()[1].name, "res/hero.M3G");
    EXPECT_EQ(a.entries()[1].size, 14u);
    EXPECT_EQ(a.entries()[1].compressedSize, 14u);  // stored
    EXPECT_EQ(a.entries()[3].size, 5000u);
    EXPECT_LT(a.entries()[3].compressedSize, 5000u);  // deflated run of one byte
    std::vector<std::string> others;
    EXPECT_EQ(a.m3gEntries(&others), (std::vector<std::string>{"res/hero.M3G", "res/level1.m3g"}));
    EXPECT_EQ(others, (std::vector<std::string>{"META-INF/MANIFEST.MF", "Game.class"}));
    EXPECT_TRUE(a.contains("Game.class"));
    EXPECT_FALSE(a.contains("res/"));
    EXPECT_TRUE(JarArchive::looksLikeZip(jar));
}

TEST(JarArchive, ReadsStoredAndDeflatedEntries) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    Bytes varied(70000);
    for (std::size_t i = 0; i < varied.size(); ++i) varied[i] = static_cast<std::uint8_t>((i * 31) ^ (i >> 7));
    writeZip(jar, {{"a.bin", varied, true}, {"b.txt", text("hello"), false}, {"empty", {}, true}});
    JarArchive a(jar.string());
    EXPECT_EQ(a.read("a.bin"), varied);  // more than one 64 KiB read chunk
    EXPECT_EQ(a.read("b.txt"), text("hello"));
    EXPECT_TRUE(a.read("empty").empty());
    EXPECT_EQ(a.read("b.txt"), text("hello"));  // again, after other reads
}

TEST(JarArchive, MissingEntryNamesArchiveAndEntry) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"a.m3g", text("x")}});
    JarArchive a(jar.string());
    const std::string m = messageOf([&] { a.read("b.m3g"); });
    EXPECT_NE(m.find(jar.string() + "!/b.m3g"), std::string::npos) << m;
    EXPECT_NE(m.find("no such entry"), std::string::npos) << m;
    EXPECT_THROW(a.read("B.M3G"), JarError);  // names are case-sensitive, as in a JVM
}

TEST(JarArchive, RejectsMissingAndNonZipFiles) {
    TempDir dir;
    EXPECT_NE(messageOf([&] { JarArchive((dir.path / "nope.jar").string()); }).find("no such archive"), std::string::npos);
    const fs::path notZip = dir.path / "scene.jar";
    std::ofstream(notZip) << "this is plain text, not a zip archive at all";
    const std::string m = messageOf([&] { JarArchive a(notZip.string()); });
    EXPECT_NE(m.find(notZip.string()), std::string::npos) << m;
    EXPECT_NE(m.find("not a zip"), std::string::npos) << m;
    EXPECT_FALSE(JarArchive::looksLikeZip(notZip));
    EXPECT_THROW(JarArchive(dir.path.string()), JarError);  // a folder
}

TEST(JarArchive, TruncatedArchiveFailsToOpen) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"a.m3g", Bytes(1000, 3)}, {"b.m3g", Bytes(1000, 4)}});
    Bytes bytes = m3gtest::readFile(jar);
    bytes.resize(bytes.size() - 30);  // cut into the central directory's end record
    std::ofstream(jar, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()),
                                                                static_cast<std::streamsize>(bytes.size()));
    EXPECT_THROW(JarArchive a(jar.string()), JarError);
}

TEST(JarArchive, CorruptEntryDataIsReportedNotReturned) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    const std::string payload = "PAYLOAD-0123456789-PAYLOAD";
    writeZip(jar, {{"stored.txt", text(payload), false}, {"other.txt", text("fine")}});
    Bytes bytes = m3gtest::readFile(jar);
    const auto at = std::search(bytes.begin(), bytes.end(), payload.begin(), payload.end());
    ASSERT_NE(at, bytes.end());
    at[10] ^= 0x01;  // one bit of the stored data: only the CRC-32 can tell
    std::ofstream(jar, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()),
                                                                static_cast<std::streamsize>(bytes.size()));
    JarArchive a(jar.string());
    const std::string m = messageOf([&] { a.read("stored.txt"); });
    EXPECT_NE(m.find("stored.txt"), std::string::npos) << m;
    EXPECT_NE(m.find("CRC-32"), std::string::npos) << m;
    EXPECT_EQ(a.read("other.txt"), text("fine"));  // the archive stays usable
}

TEST(JarArchive, LoadsAnM3gEntry) {
    TempDir dir;
    const Bytes sample = sampleSceneBytes(dir.path);
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"Game.class", Bytes(10, 1)}, {"res/scene.m3g", sample}});
    JarArchive a(jar.string());
    const LoadResult fromJar = a.load("res/scene.m3g");
    const LoadResult direct = Loader::loadDetailed(std::span<const std::uint8_t>(sample), 0);
    ASSERT_EQ(fromJar.objects.size(), direct.objects.size());
    for (std::size_t i = 0; i < direct.objects.size(); ++i)
        EXPECT_STREQ(fromJar.objects[i]->getClassName(), direct.objects[i]->getClassName()) << i;
    ASSERT_EQ(fromJar.roots.size(), 1u);
    EXPECT_STREQ(fromJar.roots[0]->getClassName(), "World");
}

TEST(JarArchive, ExternalReferencesResolveToOtherEntries) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    // res/a.m3g refers to "tex/sky.png", i.e. the entry res/tex/sky.png; a
    // file of that name next to the archive must not be the one used.
    writeZip(jar, {{"res/a.m3g", externalOnly("tex/sky.png")}, {"res/tex/sky.png", pngBytes(5, 3)}});
    fs::create_directories(dir.path / "tex");
    std::ofstream(dir.path / "tex" / "sky.png") << "decoy";
    JarArchive a(jar.string());
    const LoadResult r = a.load("res/a.m3g");
    ASSERT_EQ(r.roots.size(), 1u);
    auto* image = dynamic_cast<Image2D*>(r.roots[0].get());
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->getWidth(), 5);
    EXPECT_EQ(image->getHeight(), 3);
    EXPECT_EQ(image->pixels()[0], 0x40);
}

TEST(JarArchive, LoadErrorsNameTheArchiveEntryNotATemporaryPath) {
    TempDir dir;
    const fs::path jar = dir.path / "game.jar";
    writeZip(jar, {{"res/a.m3g", externalOnly("missing.png")}, {"res/bad.m3g", text("garbage")}});
    JarArchive a(jar.string());
    std::string m = messageOf([&] { a.load("res/a.m3g"); });
    EXPECT_NE(m.find(jar.string() + "!/res/a.m3g"), std::string::npos) << m;
    EXPECT_NE(m.find("missing.png"), std::string::npos) << m;
    EXPECT_EQ(m.find("m3g-jar-"), std::string::npos) << m;
    m = messageOf([&] { a.load("res/bad.m3g"); });
    EXPECT_NE(m.find(jar.string() + "!/res/bad.m3g"), std::string::npos) << m;
    EXPECT_THROW(a.load("res/none.m3g"), JarError);

    // Lenient: the missing reference becomes a warning, also with the archive name.
    LoaderOptions lenient;
    lenient.lenient = true;
    writeZip(dir.path / "g2.jar", {{"res/s.m3g", sampleSceneBytes(dir.path)}, {"res/t.m3g", externalOnly("gone.png")}});
    JarArchive b((dir.path / "g2.jar").string());
    const LoadResult r = b.load("res/t.m3g", lenient);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_EQ(r.warnings[0].find("m3g-jar-"), std::string::npos) << r.warnings[0];
}

TEST(JarArchive, EntriesThatLeaveTheFolderAreNotExtracted) {
    TempDir dir;
    const fs::path jar = dir.path / "evil.jar";
    writeZip(jar, {{"../escape.m3g", externalOnly("x.png")}, {"ok.m3g", externalOnly("x.png")}, {"x.png", pngBytes(2, 2)}});
    JarArchive a(jar.string());
    EXPECT_TRUE(a.contains("../escape.m3g"));
    EXPECT_THROW(a.load("../escape.m3g"), JarError);
    EXPECT_EQ(a.load("ok.m3g").roots.size(), 1u);
    EXPECT_FALSE(fs::exists(fs::temp_directory_path() / "escape.m3g"));
}
