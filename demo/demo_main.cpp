// postfx-demo: the windowed demo. Shows a demo scene (G-buffer, sun + shadow map, lighting, postfx,
// GPU tonemap) in a GLFW window with a free-flight camera and an ImGui overlay. Without a display it
// renders the scene headless, as postfx-render does, to out/<scene>.png.
#include "cli_args.h"
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "scene/scene.h"
#include "window/window_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

namespace cli = demo::cli;

namespace {

constexpr uint32_t kMaxSize = 16384;
constexpr uint32_t kMaxFrames = 100000000;

const char* kUsage =
    "usage: postfx-demo [SCENE.json] [--size WxH] [--frames N] [--no-ui] [--validation] [--hold]\n"
    "Shows SCENE.json (the built-in default scene when omitted) in a window: HDR rendering, postfx,\n"
    "GPU tonemap (ACES fitted, sRGB; the camera's ev100), an ImGui panel and a free-flight camera:\n"
    "  W/A/S/D move, Q/E down/up, Shift faster, right mouse button + move to look, Esc quits.\n"
    "Without a display (no DISPLAY / WAYLAND_DISPLAY, or GLFW cannot start) the scene is rendered\n"
    "headless, as postfx-render does, to out/default-scene.png (out/<SCENE>.png for a scene file).\n"
    "options:\n"
    "  --size WxH    window size (default 1280x720), each side 1..16384; the headless image size\n"
    "  --frames N    exit after N presented frames (headless: frames rendered before writing)\n"
    "  --no-ui       no ImGui overlay\n"
    "  --validation  Vulkan validation layer with synchronization validation (also\n"
    "                POSTFX_VALIDATION=1); any validation message fails the run (exit 1)\n"
    "  --hold        with --frames: keep the window showing the last frame until stdin is closed\n"
    "                (for screenshot tests)\n"
    "environment: POSTFX_DEVICE=<substring of the device name> picks the Vulkan device\n"
    "exit status: 0 ok, 1 on any error (one line 'postfx-demo: <message>' on stderr)\n";

struct Args {
    std::string scene;
    demo::window::AppOptions window;
    bool sizeGiven = false;
};

Args parseArgs(int argc, char** argv) {
    Args args;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) throw cli::UsageError{std::string(argv[i]) + " needs a value"};
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size") {
            cli::sizeOption(value(i), kMaxSize, args.window.width, args.window.height);
            args.sizeGiven = true;
        } else if (a == "--frames") {
            cli::uintOption(a, value(i), 1, kMaxFrames, args.window.frames);
        } else if (a == "--no-ui") {
            args.window.ui = false;
        } else if (a == "--validation") {
            args.window.validation = true;
        } else if (a == "--hold") {
            args.window.hold = true;
        } else if (a.size() > 1 && a[0] == '-') {
            throw cli::UsageError{"unknown option '" + a + "' (see --help)"};
        } else if (args.scene.empty()) {
            args.scene = a;
        } else {
            throw cli::UsageError{"more than one scene file given ('" + args.scene + "', '" + a + "')"};
        }
    }
    if (args.window.hold && args.window.frames == 0) throw cli::UsageError{"--hold needs --frames N"};
    return args;
}

int fail(const std::string& message) {
    std::fprintf(stderr, "postfx-demo: %s\n", message.c_str());
    return 1;
}

// GLFW errors: kept quiet while glfwInit decides between window and headless, printed afterwards.
std::string gGlfwError = "unknown error";
bool gReportGlfwErrors = false;
void onGlfwError(int /*code*/, const char* description) {
    gGlfwError = description ? description : "unknown error";
    if (gReportGlfwErrors) std::fprintf(stderr, "postfx-demo: GLFW: %s\n", gGlfwError.c_str());
}

bool envSet(const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0';
}

// No display: the same path as postfx-render (Renderer::render, then writeImage's CPU tonemap).
int renderHeadless(const Args& args, const demo::Scene& scene) {
    namespace fs = std::filesystem;
    const std::string name = args.scene.empty() ? "default-scene" : fs::path(args.scene).stem().string();
    std::error_code ec;
    fs::create_directories("out", ec);
    if (ec) return fail("cannot create the directory 'out': " + ec.message());
    const fs::path output = fs::absolute(fs::path("out") / (name + ".png"));

    demo::RenderOptions options;
    options.width = args.window.width;
    options.height = args.window.height;
    options.frames = std::max(args.window.frames, 1u);
    demo::HostOptions hostOptions;
    hostOptions.validation = args.window.validation;
    std::string error;
    auto host = demo::VulkanHost::create(hostOptions, error);
    if (!host) return fail("Vulkan: " + error);
    {
        auto renderer = demo::Renderer::create(*host, options, error);
        demo::ImageF image;
        if (!renderer || !renderer->render(scene, image, error)) return fail(error);
        if (!demo::writeImage(output.string(), image, scene.camera.ev100, error)) return fail(error);
    }
    if (size_t n = host->validationMessageCount(); n > 0)
        return fail(std::to_string(n) + " Vulkan validation message(s), printed above");
    std::printf("postfx-demo: no display; rendered %s to %s\n",
                args.scene.empty() ? "the default scene" : args.scene.c_str(), output.string().c_str());
    return 0;
}

int run(const Args& args) {
    demo::Scene scene = demo::defaultScene();
    std::string error;
    if (!args.scene.empty() && !demo::loadSceneFile(args.scene, scene, error)) return fail(error);

    if (!envSet("DISPLAY") && !envSet("WAYLAND_DISPLAY")) return renderHeadless(args, scene);
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        std::fprintf(stderr, "postfx-demo: cannot open a window (GLFW: %s); rendering headless\n",
                     gGlfwError.c_str());
        return renderHeadless(args, scene);
    }
    gReportGlfwErrors = true;
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        return fail("GLFW found no Vulkan loader / ICD (glfwVulkanSupported)");
    }
    const int code = demo::window::runWindow(args.window, scene);
    glfwTerminate();
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        for (int i = 1; i < argc; ++i) {
            if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
                std::fputs(kUsage, stdout);
                return 0;
            }
        }
        return run(parseArgs(argc, argv));
    } catch (const cli::UsageError& e) {
        return fail(e.message);
    } catch (const std::exception& e) {
        return fail(std::string("unexpected error: ") + e.what());
    } catch (...) {
        return fail("unexpected error");
    }
}
