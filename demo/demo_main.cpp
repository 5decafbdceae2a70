// postfx-demo: the windowed demo. Shows a demo scene (G-buffer, sun + shadow map, lighting, postfx,
// GPU tonemap) in a GLFW window with a free-flight camera and an ImGui overlay. Without a display it
// renders the scene headless, as postfx-render does, to out/<scene>.png.
#include "host/renderer.h"
#include "host/vulkan_host.h"
#include "program.h"
#include "scene/scene.h"
#include "window/window_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace cli = demo::cli;

namespace {

constexpr uint32_t kMaxFrames = 100000000;

const char* kUsage =
    "usage: postfx-demo [SCENE.json] [--size WxH] [--frames N] [--no-ui] [--validation] [--hold]\n"
    "Shows SCENE.json (the built-in default scene when omitted) in a window: HDR rendering, postfx,\n"
    "GPU tonemap (ACES fitted, sRGB; the camera's ev100), an ImGui panel and a free-flight camera:\n"
    "  W/A/S/D move, Q/E down/up, Shift faster, right mouse button + move to look, R resets the\n"
    "  view to the scene file's camera (a camera cut: postfx drops its temporal history), Esc quits.\n"
    "  The scene's lights move as the file says (velocity, intensity change; docs/scene-format.md);\n"
    "  its camera motion is not applied (the fly camera is yours).\n"
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

const cli::Program kProgram("postfx-demo", kUsage, 1);

struct Args {
    cli::CommonArgs common;           // scene, --size, --frames, --validation
    demo::window::AppOptions window;  // --size, --frames and --validation copied in
};

Args parseArgs(int argc, char** argv) {
    Args args;
    args.common.width = args.window.width;
    args.common.height = args.window.height;
    args.common.frames = args.window.frames;
    cli::parseArgs(argc, argv, kMaxFrames, args.common, [&](const std::string& a, const auto& /*next*/) {
        if (a == "--no-ui") {
            args.window.ui = false;
        } else if (a == "--hold") {
            args.window.hold = true;
        } else {
            return false;
        }
        return true;
    });
    args.window.width = args.common.width;
    args.window.height = args.common.height;
    args.window.frames = args.common.frames;
    args.window.validation = args.common.validation;
    if (args.window.hold && args.window.frames == 0) throw cli::UsageError{"--hold needs --frames N"};
    return args;
}

int fail(const std::string& message) {
    return kProgram.fail(message);
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
    const std::string& sceneFile = args.common.scene;
    const std::string name = sceneFile.empty() ? "default-scene" : fs::path(sceneFile).stem().string();
    std::error_code ec;
    fs::create_directories("out", ec);
    if (ec) return fail("cannot create the directory 'out': " + ec.message());
    const fs::path output = fs::absolute(fs::path("out") / (name + ".png"));

    demo::RenderOptions options;
    options.width = args.window.width;
    options.height = args.window.height;
    options.frames = std::max(args.window.frames, 1u);
    auto host = kProgram.createHost(args.window.validation);
    if (!host) return 1;
    std::string error;
    {
        auto renderer = demo::Renderer::create(*host, options, error);
        demo::ImageF image;
        if (!renderer || !renderer->render(scene, image, error)) return fail(error);
        if (!demo::writeImage(output.string(), image, scene.camera.ev100, error)) return fail(error);
    }
    if (int status = kProgram.validationStatus(*host)) return status;
    std::printf("postfx-demo: no display; rendered %s to %s\n",
                sceneFile.empty() ? "the default scene" : sceneFile.c_str(), output.string().c_str());
    return 0;
}

int run(const Args& args) {
    demo::Scene scene;
    if (!kProgram.loadScene(args.common.scene, scene)) return 1;

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
    return kProgram.main(argc, argv, [&] { return run(parseArgs(argc, argv)); });
}
