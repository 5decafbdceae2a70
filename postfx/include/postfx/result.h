// Result codes returned by every postfx call. Nothing in postfx asserts or exits on bad input:
// a call that cannot do what was asked returns a Status whose message names the problem.
#pragma once

#include <postfx/export.h>
#include <string>

namespace postfx {

enum class Result {
    Success = 0,
    NotReady,         // e.g. GPU timings of a frame whose queries have not completed yet
    InvalidArgument,  // a parameter or image handed in is unusable; the message names it
    Unsupported,      // the device lacks a feature, format or limit postfx needs
    OutOfMemory,      // a postfx allocation failed (host or device memory)
    VulkanError,      // a Vulkan call returned an unexpected error code
};

// A short, stable name for a result code ("InvalidArgument").
POSTFX_API const char* resultName(Result result);

struct [[nodiscard]] Status {
    Result code = Result::Success;
    std::string message;  // empty on success; otherwise one line naming what is wrong

    bool ok() const { return code == Result::Success; }
    explicit operator bool() const { return ok(); }

    static Status success() { return {}; }
};

enum class MessageSeverity { Info, Warning, Error };

// Optional host callback for what postfx cannot return: warnings (a feature it falls back from, timings
// measured elsewhere that it skips). Errors are returned as a Status and never sent here as well, so a
// host that prints both sees each message once. Called on the thread that made the postfx call.
using MessageCallback = void (*)(MessageSeverity severity, const char* message, void* userData);

}  // namespace postfx
