// What postfx-render and postfx-demo have in common around their own work: the options both take
// ([SCENE.json] --size --frames --validation), the scene (a file or the built-in one), the Vulkan host,
// one-line error messages and exit statuses, and main()'s --help and exception handling.
#pragma once

#include "cli_args.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace demo::cli {

// The options both programs take. The caller sets the defaults it wants before parseArgs.
struct CommonArgs {
    std::string scene;  // SCENE.json; empty: the built-in default scene
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;  // --frames N, N in [1, maxFrames]; left as set when not given
    bool validation = false;
};

// The program's own options: called first with each argument; returns whether it took it, taking its
// value with next() (which throws "OPTION needs a value" when there is none).
using OwnOption = std::function<bool(const std::string& arg, const std::function<std::string()>& next)>;

// Reads argv[1..]: each argument goes to `own` first, then is one of the common options (--size WxH with
// sides up to 16384 and the image's memory within kImageMemoryBudget, --frames N up to maxFrames,
// --validation) or the scene file. Throws UsageError for an unknown option ("unknown option '-x' (see
// --help)"), a second scene file or a --size over the budget.
void parseArgs(int argc, char** argv, uint32_t maxFrames, CommonArgs& common, const OwnOption& own);

class Program {
public:
    // name: the prefix of error lines; usage: printed for --help / -h; usageStatus: the exit status of a
    // command-line mistake.
    Program(const char* name, const char* usage, int usageStatus)
        : name_(name), usage_(usage), usageStatus_(usageStatus) {}

    // Prints "NAME: message" on stderr; returns status.
    int fail(const std::string& message, int status = 1) const;

    // The body of main(): --help or -h anywhere prints the usage on stdout (exit 0); otherwise run()'s
    // status, with a UsageError it throws printed by fail() with usageStatus and any other exception as
    // "unexpected error: ..." (1).
    int main(int argc, char** argv, const std::function<int()>& run) const;

    // The scene of path, or the built-in default scene when path is empty; false after printing the error
    // (the file's path first).
    bool loadScene(const std::string& path, Scene& scene) const;

    // The Vulkan host (the validation layer on when asked); nullptr after printing "Vulkan: <error>".
    std::unique_ptr<VulkanHost> createHost(bool validation) const;

    // Destroys the host's device and instance (VulkanHost::destroy: the validation layer reports objects
    // left on the device there), then returns status, or 1 after printing how many messages the
    // validation layer printed (above), those at destruction included.
    int validationStatus(VulkanHost& host, int status = 0) const;

private:
    const char* name_;
    const char* usage_;
    int usageStatus_;
};

}  // namespace demo::cli
