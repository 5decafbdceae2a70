#include "program.h"

#include <cstdio>
#include <exception>

namespace demo::cli {

namespace {
constexpr uint32_t kMaxSize = 16384;
}

void parseArgs(int argc, char** argv, uint32_t maxFrames, CommonArgs& common, const OwnOption& own) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto next = [&] { return optionValue(argc, argv, i); };
        if (own(a, next)) continue;
        if (a == "--size") {
            sizeOption(next(), kMaxSize, common.width, common.height);
            checkImageMemory(common.width, common.height);
        } else if (a == "--frames") {
            uintOption(a, next(), 1, maxFrames, common.frames);
        } else if (a == "--validation") {
            common.validation = true;
        } else if (a.size() > 1 && a[0] == '-') {
            throw UsageError{"unknown option '" + a + "' (see --help)"};
        } else if (common.scene.empty()) {
            common.scene = a;
        } else {
            throw UsageError{"more than one scene file given ('" + common.scene + "', '" + a + "')"};
        }
    }
}

int Program::fail(const std::string& message, int status) const {
    std::fprintf(stderr, "%s: %s\n", name_, message.c_str());
    return status;
}

int Program::main(int argc, char** argv, const std::function<int()>& run) const {
    try {
        for (int i = 1; i < argc; ++i) {
            if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
                std::fputs(usage_, stdout);
                return 0;
            }
        }
        return run();
    } catch (const UsageError& e) {
        return fail(e.message, usageStatus_);
    } catch (const std::exception& e) {
        return fail(std::string("unexpected error: ") + e.what());
    } catch (...) {
        return fail("unexpected error");
    }
}

bool Program::loadScene(const std::string& path, Scene& scene) const {
    if (path.empty()) {
        scene = defaultScene();
        return true;
    }
    std::string error;
    if (loadSceneFile(path, scene, error)) return true;
    fail(error);
    return false;
}

std::unique_ptr<VulkanHost> Program::createHost(bool validation) const {
    HostOptions options;
    options.validation = validation;
    std::string error;
    auto host = VulkanHost::create(options, error);
    if (!host) fail("Vulkan: " + error);
    return host;
}

int Program::validationStatus(VulkanHost& host, int status) const {
    const size_t before = host.validationMessageCount();
    host.destroy();
    const size_t n = host.validationMessageCount();
    if (n == 0) return status;
    return fail(std::to_string(n) + " Vulkan validation message(s), printed above (" +
                std::to_string(n - before) + " while destroying the device and instance)");
}

}  // namespace demo::cli
