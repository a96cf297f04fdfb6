// Replays every reproducer the fuzzers found (tests/fuzz/regressions/TARGET,
// written by scripts/fuzz) through the rules of its libFuzzer target
// (tests/fuzz/FuzzChecks.h): each input loads or fails with an IOException,
// and what loads saves and loads again. Under the ASan + UBSan build
// (scripts/test) this is also the memory, leak and undefined-behaviour check
// of each input.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "FuzzChecks.h"
#include "M3GTestBytes.h"

namespace {

template <class Check>
void replay(const std::string& target, Check check) {
    const auto files = m3gtest::regressionFiles(target);
    // A missing or empty folder would make the replay pass without checking anything.
    ASSERT_FALSE(files.empty()) << "tests/fuzz/regressions/" << target << " holds no reproducer";
    for (const auto& f : files) {
        SCOPED_TRACE(f.string());
        const m3gtest::Bytes bytes = m3gtest::readFile(f);
        try {
            check(std::span<const std::uint8_t>(bytes));
        } catch (const m3gfuzz::Failure& failure) {
            ADD_FAILURE() << failure.what;
        }
    }
    std::printf("[ replayed ] %zu %s reproducer(s)\n", files.size(), target.c_str());
}

}  // namespace

TEST(FuzzRegressions, LoaderInputsLoadOrFailWithIOException) { replay("loader", m3gfuzz::checkLoader); }

TEST(FuzzRegressions, PngInputsLoadOrFailWithIOException) { replay("png", m3gfuzz::checkPng); }

TEST(FuzzRegressions, JpegInputsLoadOrFailWithIOException) { replay("jpeg", m3gfuzz::checkJpeg); }

TEST(FuzzRegressions, RoundTripInputsSaveAndLoadAgain) {
    replay("roundtrip", m3gfuzz::checkRoundTrip);
    // A reproducer of one target is a hostile input for the others too.
    replay("loader", m3gfuzz::checkRoundTrip);
}

// The checksum repair of FuzzInput.h, which every reproducer goes through:
// a section whose Adler-32 was damaged loads again once repaired.
TEST(FuzzRegressions, ChecksumRepairRestoresSectionChecksums) {
    m3gtest::FileSpec spec;
    const m3gtest::Bytes good = spec.build();
    m3gtest::Bytes bad = good;
    bad.back() ^= 0x5A;  // last byte of the header section's Adler-32
    EXPECT_EQ(m3gfuzz::repairChecksums(bad), good);
    m3gtest::Bytes wrongSize = good;
    wrongSize[29] ^= 1;  // TotalFileSize
    EXPECT_EQ(m3gfuzz::repairChecksums(wrongSize), good);
}
