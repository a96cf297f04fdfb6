// Waiting for a frame's fence (render-vk/FrameWait.h): the
// M3G_VK_FENCE_SPIN_US budget's parsing, and waitForFence on fences that are
// signalled already, soon, and only after the polling budget has run out.
#include "VkTestSupport.h"

#include <chrono>
#include <vector>

#include "Context.h"
#include "FrameWait.h"

using namespace m3g;
using m3gtest::VkTest;

TEST(FrameWait, SpinBudgetParsing) {
    EXPECT_EQ(vk::parseFenceSpinMicros("0"), 0u);
    EXPECT_EQ(vk::parseFenceSpinMicros("1000"), 1000u);
    EXPECT_EQ(vk::parseFenceSpinMicros("100000"), vk::kMaxFenceSpinMicros);
    EXPECT_EQ(vk::parseFenceSpinMicros("100001"), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros("99999999999999999999999"), std::nullopt);  // no overflow back into range
    EXPECT_EQ(vk::parseFenceSpinMicros(""), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros(nullptr), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros("-5"), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros("+5"), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros(" 5"), std::nullopt);
    EXPECT_EQ(vk::parseFenceSpinMicros("12us"), std::nullopt);
}

namespace {

class FrameWaitTest : public VkTest {
protected:
    void SetUp() override {
        VkTest::SetUp();
        ctx_ = vk::Context::shared();
    }
    void TearDown() override {
        for (VkFence f : fences_) vkDestroyFence(ctx_->device(), f, nullptr);
        ctx_.reset();
        VkTest::TearDown();
    }
    VkFence fence(bool signalled) {
        VkFenceCreateInfo fi{};
        fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        fi.flags = signalled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
        VkFence f = VK_NULL_HANDLE;
        EXPECT_EQ(vkCreateFence(ctx_->device(), &fi, nullptr, &f), VK_SUCCESS);
        fences_.push_back(f);
        return f;
    }
    std::shared_ptr<vk::Context> ctx_;
    std::vector<VkFence> fences_;
};

using Clock = std::chrono::steady_clock;
double millisSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

TEST_F(FrameWaitTest, SignalledFencesAreSeenWithOrWithoutPolling) {
    // (No upper bound on the time taken: a test never fails on a slow
    // machine. The lower bounds below cannot.)
    for (std::uint32_t spin : {0u, 50000u}) {
        const VkFence f = fence(true);
        EXPECT_EQ(vk::waitForFence(ctx_->device(), f, spin, 0), VK_SUCCESS) << "spin " << spin;
    }
}

TEST_F(FrameWaitTest, AFenceSignalledBySubmitIsSeenWhilePolling) {
    const VkFence f = fence(false);
    ctx_->submit(std::span<const VkCommandBuffer>(), f);  // an empty batch: the queue signals it
    EXPECT_EQ(vk::waitForFence(ctx_->device(), f, vk::kMaxFenceSpinMicros), VK_SUCCESS);
    EXPECT_EQ(vkGetFenceStatus(ctx_->device(), f), VK_SUCCESS);
}

TEST_F(FrameWaitTest, PastTheBudgetItWaitsInVkWaitForFences) {
    // Never signalled: 2 ms of polling, then vkWaitForFences with a 30 ms
    // limit, which reports the timeout.
    const VkFence f = fence(false);
    const auto t0 = Clock::now();
    EXPECT_EQ(vk::waitForFence(ctx_->device(), f, 2000, 30'000'000), VK_TIMEOUT);
    EXPECT_GE(millisSince(t0), 31.0) << "the polling budget and the timeout should both have passed";
    // Without a budget, the timeout alone.
    const auto t1 = Clock::now();
    EXPECT_EQ(vk::waitForFence(ctx_->device(), f, 0, 10'000'000), VK_TIMEOUT);
    EXPECT_GE(millisSince(t1), 9.5);
}
