// Linked into every executable of the sanitizer build (POSTFX_SANITIZE, cmake/Sanitizers.cmake) only.
// LeakSanitizer reports at exit; by then the Vulkan loader has dlclose()d the driver and the layers it
// loaded, and a leak they made has no module name left for tests/sanitizers/lsan.supp to match (nor
// for a reader). Debian 12's loader (1.3.239) predates VK_LOADER_DISABLE_DYNAMIC_LIBRARY_UNLOADING, so
// this executable defines dlclose(), which the loader's call binds to, as "keep it loaded": no shared
// library is unloaded before exit. Nothing in postfx or the demo calls dlclose.
extern "C" int dlclose(void*) {
    return 0;
}
