#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace bench {

constexpr size_t kBarWidth = 20;

Progress::Progress(size_t total)
    : total_(std::max<size_t>(total, 1)), terminal_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
    if (lineOpen_) std::fputc('\n', stderr);
}

void Progress::show(const std::string& what) {
    const size_t filled = std::min(kBarWidth, done_ * kBarWidth / total_);
    std::string line = "[" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "] " +
                       std::to_string(done_) + "/" + std::to_string(total_) + " " + what;
    if (terminal_) {
        const size_t width = line.size();
        if (width < lastWidth_) line += std::string(lastWidth_ - width, ' ');  // erase the longer old line
        lastWidth_ = width;
        std::fprintf(stderr, "\r%s", line.c_str());
        lineOpen_ = true;
    } else {
        std::fprintf(stderr, "%s\n", line.c_str());
    }
    std::fflush(stderr);
}

void Progress::message(const std::string& text) {
    if (lineOpen_) {
        std::fputc('\n', stderr);
        lineOpen_ = false;
        lastWidth_ = 0;
    }
    std::fprintf(stderr, "%s\n", text.c_str());
    std::fflush(stderr);
}

}  // namespace bench
