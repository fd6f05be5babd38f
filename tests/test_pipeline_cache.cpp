// test_pipeline_cache.cpp - the driver's pipeline cache kept on disk
// (render/disk_pipeline_cache.h), on lavapipe with validation on, in an XDG_CACHE_HOME of its
// own: a headless run with no file is a miss and writes it; the next run is a hit, its
// VkPipelineCache made from the file's blob and every pipeline created with that cache;
// --no-cache neither reads nor writes it; and a file of
// another device, with a driver header of another device, cut short, with a flipped byte or a
// wrong checksum is rejected (saying why), the cache starting empty, and the next save
// replaces it with a good one.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/pipeline_file.h"
#include "test_support.h"
#include "util/cache_file.h"

// Every pipeline cache this test binary makes, with the bytes it was given, and the cache
// each pipeline is created with: idview's calls land here first, then go on to the loader's.
std::map<VkPipelineCache, size_t> cacheInitialBytes;
std::vector<VkPipelineCache> pipelineCaches; // one per pipeline created

namespace {
template <typename Fn>
Fn nextVulkan(const char* name) {
    return reinterpret_cast<Fn>(dlsym(RTLD_NEXT, name));
}

// vkCreateGraphicsPipelines or vkCreateComputePipelines (`Fn`, called `name`), noted.
template <typename Fn, typename Info>
VkResult createPipelines(const char* name, VkDevice device, VkPipelineCache cache, uint32_t count,
                         const Info* infos, const VkAllocationCallbacks* allocator,
                         VkPipeline* pipelines) {
    static const auto next = nextVulkan<Fn>(name);
    pipelineCaches.insert(pipelineCaches.end(), count, cache);
    return next(device, cache, count, infos, allocator, pipelines);
}
} // namespace

extern "C" {
VKAPI_ATTR VkResult VKAPI_CALL vkCreatePipelineCache(VkDevice device,
                                                     const VkPipelineCacheCreateInfo* info,
                                                     const VkAllocationCallbacks* allocator,
                                                     VkPipelineCache* cache) {
    static const auto next = nextVulkan<PFN_vkCreatePipelineCache>("vkCreatePipelineCache");
    const VkResult result = next(device, info, allocator, cache);
    if (result == VK_SUCCESS) cacheInitialBytes[*cache] = info->initialDataSize;
    return result;
}
VKAPI_ATTR VkResult VKAPI_CALL vkCreateGraphicsPipelines(VkDevice d, VkPipelineCache c, uint32_t n,
                                                         const VkGraphicsPipelineCreateInfo* i,
                                                         const VkAllocationCallbacks* a,
                                                         VkPipeline* p) {
    return createPipelines<PFN_vkCreateGraphicsPipelines>("vkCreateGraphicsPipelines", d, c, n, i,
                                                          a, p);
}
VKAPI_ATTR VkResult VKAPI_CALL vkCreateComputePipelines(VkDevice d, VkPipelineCache c, uint32_t n,
                                                        const VkComputePipelineCreateInfo* i,
                                                        const VkAllocationCallbacks* a,
                                                        VkPipeline* p) {
    return createPipelines<PFN_vkCreateComputePipelines>("vkCreateComputePipelines", d, c, n, i, a,
                                                         p);
}
}

namespace {

namespace fs = std::filesystem;

// XDG_CACHE_HOME points at a fresh folder for the whole suite, and back afterwards. The
// suite's first headless run (a cold start) leaves the good file the tests start from.
class PipelineDiskCache : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        root_ = fs::temp_directory_path() / ("idview_pipelines_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_);
        if (const char* old = std::getenv("XDG_CACHE_HOME")) saved_ = old;
        setenv("XDG_CACHE_HOME", root_.c_str(), 1);
        app::SceneSettings source;
        source.builtin = "tiles";
        scene_ = new app::LoadedScene(app::loadScene(source));
        pipelineCaches.clear();
        cold_ = render(options());
        coldCaches_ = pipelineCaches;
    }
    static void TearDownTestSuite() {
        if (saved_)
            setenv("XDG_CACHE_HOME", saved_->c_str(), 1);
        else
            unsetenv("XDG_CACHE_HOME");
        delete scene_;
        std::error_code ignored;
        fs::remove_all(root_, ignored);
    }

    static app::Options options() { return testing_support::headlessOptions(32, 32); }
    static app::HeadlessResult render(const app::Options& o) {
        return app::renderHeadless(o, scene_->scene, app::initialCamera(*scene_, 1.0f));
    }
    // The one pipeline file in the folder (the tests run on one device).
    // The pipeline cache's files in the cache folder (beside them: --clear auto's timings).
    static std::vector<fs::path> files(const std::string& prefix = "pipelines-") {
        std::vector<fs::path> found;
        if (fs::exists(root_ / "idview"))
            for (const auto& e : fs::directory_iterator(root_ / "idview"))
                if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
        return found;
    }

    static inline fs::path root_;
    static inline std::optional<std::string> saved_;
    static inline app::LoadedScene* scene_ = nullptr;
    static inline app::HeadlessResult cold_;
    static inline std::vector<VkPipelineCache> coldCaches_; // of each pipeline of the cold run
};

TEST_F(PipelineDiskCache, ColdRunWritesItAndTheNextCreatesItsPipelinesFromIt) {
    EXPECT_EQ(cold_.pipelineCache, "miss");
    EXPECT_EQ(cold_.validationMessages, 0u);
    EXPECT_GT(cold_.firstFrameMs, 0.0);
    // The compute passes and the scene pipeline, each with an empty cache of this run's.
    ASSERT_GE(coldCaches_.size(), 2u);
    for (VkPipelineCache cache : coldCaches_) {
        ASSERT_NE(cache, VK_NULL_HANDLE);
        EXPECT_EQ(cacheInitialBytes[cache], 0u);
    }
    const std::vector<fs::path> written = files();
    ASSERT_EQ(written.size(), 1u) << "the headless run saved its cache";
    EXPECT_EQ(files("clear-paths-").size(), 1u) << "--clear auto kept its timings beside it";
    const size_t blobBytes = fs::file_size(written[0]) - render::kPipelineFileHeaderBytes;
    ASSERT_GE(blobBytes, sizeof(VkPipelineCacheHeaderVersionOne));

    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, options());
        const render::DiskPipelineCache& cache = rig.renderer.driverCache();
        EXPECT_EQ(cache.status(), "hit");
        EXPECT_EQ(cache.file(), written[0]);
        EXPECT_EQ(cacheInitialBytes[cache.handle()], blobBytes) << "made from the file's blob";
        const size_t before = pipelineCaches.size() - cache.created(); // the renderer's made
        rig.renderer.setScene(scene_->scene, options().live.render);
        // Every pipeline of the warm start, as many as the cold one made, from that cache.
        EXPECT_EQ(cache.created(), coldCaches_.size());
        EXPECT_EQ(pipelineCaches.size() - before, coldCaches_.size());
        for (size_t i = before; i < pipelineCaches.size(); ++i)
            EXPECT_EQ(pipelineCaches[i], cache.handle()) << "pipeline " << i;
        // Drivers that keep pipelines in the cache say they found them there (lavapipe keeps
        // none: its data is its header alone).
        if (blobBytes > sizeof(VkPipelineCacheHeaderVersionOne) &&
            rig.device.info().pipelineCreationFeedback) {
            EXPECT_EQ(cache.hits(), cache.created());
        }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

TEST_F(PipelineDiskCache, NoCacheNeitherReadsNorWrites) {
    const std::vector<fs::path> before = files();
    ASSERT_EQ(before.size(), 1u);
    const auto written = fs::last_write_time(before[0]);
    app::Options o = options();
    o.live.scene.cadCache = false;
    const app::HeadlessResult off = render(o);
    EXPECT_EQ(off.pipelineCache, "off");
    EXPECT_EQ(off.validationMessages, 0u);
    EXPECT_EQ(files(), before);
    EXPECT_EQ(fs::last_write_time(before[0]), written);
}

// Writes `bytes` as the device's file, makes a cache of it, and returns its status; then
// saves, and checks that the file is now good and read back as a hit.
std::string afterPlanting(const vk::Device& device, const fs::path& folder, const fs::path& file,
                          const std::string& bytes) {
    EXPECT_EQ(util::writeFileAtomically(file, {bytes}), "");
    std::string status;
    {
        const render::DiskPipelineCache cache(device, folder);
        status = cache.status();
        EXPECT_EQ(cache.save(), "");
    }
    const render::DiskPipelineCache again(device, folder);
    EXPECT_EQ(again.status(), "hit") << "replaced after: " << status;
    return status;
}

TEST_F(PipelineDiskCache, BadFilesAreRejectedAndReplaced) {
    ASSERT_EQ(files().size(), 1u);
    const fs::path file = files()[0];
    const std::string good = *util::readWholeFile(file);
    constexpr size_t head = render::kPipelineFileHeaderBytes;
    ASSERT_GE(good.size(), head + sizeof(VkPipelineCacheHeaderVersionOne));

    vk::Instance instance({true, {}});
    {
        const vk::Device device(instance, vk::chooseDevice(instance.devices(), ""));
        const render::PipelineCacheIdentity id = render::pipelineCacheIdentity(device.physical());
        const std::string blob = good.substr(head);
        const fs::path folder = file.parent_path();
        auto planted = [&](const std::string& bytes) {
            return afterPlanting(device, folder, file, bytes);
        };

        render::PipelineCacheIdentity other = id;
        other.uuid[3] ^= 0x40;
        EXPECT_EQ(planted(render::encodePipelineFile(other, blob)),
                  "rejected: made by another device or driver");
        std::string otherDriver = blob;
        otherDriver[16] ^= 0x40; // in the driver header's pipelineCacheUUID
        EXPECT_EQ(planted(render::encodePipelineFile(id, otherDriver)),
                  "rejected: the driver's header names another device");
        EXPECT_EQ(planted(good.substr(0, good.size() - 8)),
                  "rejected: truncated (" + std::to_string(blob.size() - 8) + " of " +
                      std::to_string(blob.size()) + " bytes)");
        std::string flipped = good;
        flipped[head + blob.size() / 2] ^= 0x01;
        EXPECT_EQ(planted(flipped), "rejected: checksum mismatch");
        std::string wrongSum = good;
        wrongSum[head - 8] ^= 0x01; // the checksum's first byte
        EXPECT_EQ(planted(wrongSum), "rejected: checksum mismatch");
        EXPECT_EQ(planted(good), "hit");
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

} // namespace
