#include <postfx/result.h>

namespace postfx {

const char* resultName(Result result) {
    switch (result) {
        case Result::Success:
            return "Success";
        case Result::NotReady:
            return "NotReady";
        case Result::InvalidArgument:
            return "InvalidArgument";
        case Result::Unsupported:
            return "Unsupported";
        case Result::OutOfMemory:
            return "OutOfMemory";
        case Result::VulkanError:
            return "VulkanError";
    }
    return "Unknown";
}

}  // namespace postfx
