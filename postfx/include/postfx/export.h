// POSTFX_API marks postfx's public functions and classes: the only symbols libpostfx.so exports (the
// library is compiled with hidden visibility, postfx/CMakeLists.txt). Empty where it is not needed.
#pragma once

// POSTFX_INTERNAL marks what a POSTFX_API class holds but does not export (Context::Impl).
#if defined(__GNUC__) || defined(__clang__)
#define POSTFX_API __attribute__((visibility("default")))
#define POSTFX_INTERNAL __attribute__((visibility("hidden")))
#else
#define POSTFX_API
#define POSTFX_INTERNAL
#endif
