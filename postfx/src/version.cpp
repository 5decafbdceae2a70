// The library's version, as built (postfx/version.h is generated from the project's version).
#include <postfx/version.h>

namespace postfx {

uint32_t version() {
    return POSTFX_VERSION;
}

const char* versionString() {
    return POSTFX_VERSION_STRING;
}

}  // namespace postfx
