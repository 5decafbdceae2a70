// Every public header of postfx compiles in a consumer, and the headers' version is the library's.
// Prints "postfx <version>"; exit status 1 when the versions differ.
#include <postfx/postfx.h>
#include <postfx/reference.h>

#include <cstdio>
#include <cstring>

int main() {
    const bool same = postfx::version() == postfx::kHeaderVersion &&
                      std::strcmp(postfx::versionString(), POSTFX_VERSION_STRING) == 0;
    std::printf("postfx %s (headers %s)\n", postfx::versionString(), POSTFX_VERSION_STRING);
    postfx::FrameInfo frame;  // the public structs are complete types here
    frame.fog.enabled = true;
    return same && postfx::validateFogSettings(frame.fog).ok() ? 0 : 1;
}
