// The renderer's pipeline cache keeps at most its capacity of the most
// recently used pipelines between frames (render-vk/Pipelines.h), so that a
// long-lived viewer does not keep every key it ever drew. Driven directly on
// the shared device with small capacities; each key is a real pipeline
// compiled by lavapipe, under the validation layer.
#include "VkTestSupport.h"

#include <cstdint>
#include <vector>

#include "Context.h"
#include "Pipelines.h"

namespace {

using m3g::vk::PipelineKey;
using m3g::vk::Pipelines;

/// Distinct keys: blend mode 0..4 times lit with 0..8 directional lights.
PipelineKey keyNumber(int i) {
    PipelineKey key;
    key.blend = static_cast<std::uint8_t>(i % 5);
    key.lighting = 1;
    key.lightCount = static_cast<std::uint8_t>(i / 5);
    for (int l = 0; l < key.lightCount; ++l) key.lightModes |= static_cast<std::uint16_t>(1u << (2 * l));
    return key;
}

struct Counters {
    std::uint64_t created, evicted, live;
    static Counters now() {
        const m3g::vk::RenderStats s = m3g::vk::renderStats();
        return {s.pipelinesCreated, s.pipelinesEvicted, s.livePipelines};
    }
};

class PipelineCacheTest : public m3gtest::VkTest {};

TEST_F(PipelineCacheTest, KeepsTheMostRecentlyUsedWithinItsCapacity) {
    const Counters before = Counters::now();
    {
        Pipelines pipelines(m3g::vk::Context::get(), 4);
        const PipelineKey hot = keyNumber(0);
        const VkPipeline hotPipeline = pipelines.get(hot);
        // Ten frames, each drawing the hot key and one key never seen before.
        for (int frame = 1; frame <= 10; ++frame) {
            EXPECT_EQ(pipelines.get(hot), hotPipeline) << "frame " << frame << ": the key used every frame was recreated";
            pipelines.get(keyNumber(frame));
            pipelines.endFrame();
            EXPECT_LE(pipelines.size(), 4u) << "after frame " << frame;
        }
        Counters after = Counters::now();
        EXPECT_EQ(after.created - before.created, 11u);  // the hot key once, ten new ones
        EXPECT_EQ(after.evicted - before.evicted, 7u);    // 11 made, 4 kept
        EXPECT_EQ(after.live - before.live, 4u);
        // Kept: the hot key and the last three frames' keys (8, 9, 10).
        for (int i : {8, 9, 10}) pipelines.get(keyNumber(i));
        EXPECT_EQ(Counters::now().created, after.created) << "a recently used key was not kept";
        // Key 1 was the least recently used: evicted, so made again.
        pipelines.get(keyNumber(1));
        EXPECT_EQ(Counters::now().created, after.created + 1);
        pipelines.endFrame();
        EXPECT_EQ(pipelines.size(), 4u);
    }
    const Counters gone = Counters::now();
    EXPECT_EQ(gone.live, before.live) << "the destructor left pipelines alive";
}

TEST_F(PipelineCacheTest, AFrameThatNeedsMoreThanTheCapacityKeepsThemUntilItEnds) {
    Pipelines pipelines(m3g::vk::Context::get(), 2);
    std::vector<VkPipeline> made;
    for (int i = 0; i < 5; ++i) made.push_back(pipelines.get(keyNumber(i)));
    pipelines.endFrame();
    // All five were used by the frame that just ended: none is destroyed,
    // or a frame drawing them all would recreate them every time.
    EXPECT_EQ(pipelines.size(), 5u);
    const Counters settled = Counters::now();
    for (int i = 0; i < 5; ++i) EXPECT_EQ(pipelines.get(keyNumber(i)), made[static_cast<std::size_t>(i)]);
    EXPECT_EQ(Counters::now().created, settled.created);
    pipelines.endFrame();
    EXPECT_EQ(pipelines.size(), 5u);

    // A frame that uses one of them: back down to the capacity, keeping it.
    EXPECT_EQ(pipelines.get(keyNumber(3)), made[3]);
    pipelines.endFrame();
    EXPECT_EQ(pipelines.size(), 2u);
    EXPECT_EQ(Counters::now().evicted - settled.evicted, 3u);
    EXPECT_EQ(pipelines.get(keyNumber(3)), made[3]);
    EXPECT_EQ(Counters::now().created, settled.created);
}

TEST_F(PipelineCacheTest, ReplacesItsVulkanPipelineCacheAfterManyEvictions) {
    // The VkPipelineCache keeps every shader variant compiled through it;
    // after evictions, once more than four capacities' worth went through
    // it, it is replaced by an empty one. Pipelines made before stay valid.
    Pipelines pipelines(m3g::vk::Context::get(), 1);
    const VkPipeline first = pipelines.get(keyNumber(0));
    pipelines.endFrame();
    for (int frame = 1; frame <= 6; ++frame) {
        pipelines.get(keyNumber(0));
        pipelines.get(keyNumber(frame));
        pipelines.endFrame();
    }
    EXPECT_EQ(pipelines.cacheResets(), 1u);  // replaced when the fifth (> 4 x 1) had gone through it
    EXPECT_EQ(pipelines.get(keyNumber(0)), first);
    EXPECT_EQ(pipelines.size(), 2u);  // key 0 and key 6, both used by the last frame
}

}  // namespace
