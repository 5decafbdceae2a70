// demo::writeImage and demo::readImage: load the OpenImageIO module once, on first use, and call it
// (image_io.h says why it is a module).
#include "host/image_io.h"
#include "scene/scene.h"

#include <dlfcn.h>

namespace demo {
namespace {

struct LoadedModule {
    const ImageIoFunctions* functions = nullptr;
    std::string error;  // why it could not be loaded
};

// Opened by its path in the build (POSTFX_DEMO_IMAGE_IO_MODULE, demo/host/CMakeLists.txt), else by its
// name (LD_LIBRARY_PATH, the system's folders). Never unloaded: its libraries stay until the process
// ends, as a linked library's would.
const LoadedModule& module() {
    static const LoadedModule loaded = [] {
        LoadedModule m;
        void* handle = dlopen(POSTFX_DEMO_IMAGE_IO_MODULE, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const std::string byPath = dlerror();
            handle = dlopen(kImageIoModule, RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                m.error = "cannot load the image file module: " + byPath + "; " + dlerror();
                return m;
            }
        }
        using Entry = const ImageIoFunctions* (*)();
        const auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageIoEntry));
        if (!entry) {
            m.error = std::string("the image file module has no ") + kImageIoEntry;
            return m;
        }
        m.functions = entry();
        return m;
    }();
    return loaded;
}

}  // namespace

bool writeImage(const std::string& path, const ImageF& image, float ev100, std::string& error) {
    const LoadedModule& m = module();
    if (!m.functions) {
        error = "cannot write '" + path + "': " + m.error;
        return false;
    }
    // Photometric exposure (Lagarde & de Rousiers 2014): saturation-based, max luminance 1.2·2^EV100.
    return m.functions->write(path, image, exposureFromEv100(ev100), error);
}

bool readImage(const std::string& path, ImageF& image, std::string& error) {
    const LoadedModule& m = module();
    if (!m.functions) {
        error = "cannot read '" + path + "': " + m.error;
        return false;
    }
    return m.functions->read(path, image, error);
}

bool writePng8(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
               const std::vector<uint8_t>& pixels, std::string& error) {
    const LoadedModule& m = module();
    if (!m.functions) {
        error = "cannot write '" + path + "': " + m.error;
        return false;
    }
    return m.functions->writePng8(path, width, height, channels, pixels, error);
}

}  // namespace demo
