// The progress bar on stderr: "[#####.....] 12/40 fog_default postfx-fog steps=64 jitter=on noise=128".
// On a terminal one line updated in place (carriage return); otherwise one line per update.
#pragma once

#include <cstddef>
#include <string>

namespace bench {

class Progress {
public:
    explicit Progress(size_t total);
    ~Progress();  // ends the line

    // Shows `what` as the item now running (done items: `done()` so far).
    void show(const std::string& what);
    // One item finished.
    void advance() { ++done_; }
    // A line of its own (a warning), without breaking the bar.
    void message(const std::string& text);
    size_t done() const { return done_; }

private:
    size_t total_;
    size_t done_ = 0;
    bool terminal_;
    bool lineOpen_ = false;
    size_t lastWidth_ = 0;
};

}  // namespace bench
