// The demo's image files (demo/host/image_io.cpp): an EXR holds 32-bit float RGBA, so that radiance in
// physical units keeps its range and precision (half would clip at 65504 and round to 11 bits).
#include "host/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

// The pixel type of each channel of an OpenEXR file, from its header's "channels" attribute (OpenEXR
// file layout: magic, version, then attributes name\0 type\0 size value, ended by an empty name; a
// chlist value holds name\0 pixelType(int32) pLinear(u8) reserved(3) xSampling ySampling(int32) per
// channel, ended by \0). Pixel types: 0 UINT, 1 HALF, 2 FLOAT. Empty on a malformed header.
std::vector<std::pair<std::string, int32_t>> exrChannelTypes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    const auto readString = [&](size_t& at) {
        std::string s;
        while (at < bytes.size() && bytes[at] != 0)
            s += bytes[at++];
        ++at;
        return s;
    };
    const auto readInt = [&](size_t at) {
        int32_t v = 0;
        if (at + 4 <= bytes.size()) std::memcpy(&v, &bytes[at], 4);  // little-endian, as x86 and ARM
        return v;
    };
    std::vector<std::pair<std::string, int32_t>> channels;
    if (bytes.size() < 8 || readInt(0) != 20000630) return channels;  // the magic number
    for (size_t at = 8; at < bytes.size();) {
        const std::string name = readString(at);
        if (name.empty()) break;
        const std::string type = readString(at);
        const int32_t size = readInt(at);
        at += 4;
        if (name == "channels" && type == "chlist") {
            for (size_t c = at; c < at + size_t(size);) {
                const std::string channel = readString(c);
                if (channel.empty()) break;
                channels.emplace_back(channel, readInt(c));
                c += 16;
            }
            return channels;
        }
        at += size_t(std::max(size, 0));
    }
    return channels;
}

TEST(DemoImageIo, ExrIsWrittenAs32BitFloat) {
    // Beyond half's range (a 100,000 lux sun's radiance) and between half's steps near 1.
    const float values[] = {1e5f,  65520.0f, 1.0f + 1.0f / 1048576.0f,  3.0e-8f,
                            0.25f, 7.5e6f,   1.0f - 1.0f / 16777216.0f, 0.5f};
    demo::ImageF image;
    image.width = 2;
    image.height = 1;
    image.rgba.assign(std::begin(values), std::end(values));
    const std::string path = ::testing::TempDir() + "/postfx_demo_image_io.exr";
    std::string error;
    ASSERT_TRUE(demo::writeImage(path, image, 15.0f, error)) << error;

    // The file's pixel type, from its header: FLOAT in each of the four channels.
    const auto channels = exrChannelTypes(path);
    ASSERT_EQ(channels.size(), 4u) << path << ": no or a malformed channel list";
    for (const auto& [name, type] : channels)
        EXPECT_EQ(type, 2) << "channel " << name << ": pixel type " << type << " (0 uint, 1 half, 2 float)";

    // And every value back exactly.
    demo::ImageF back;
    ASSERT_TRUE(demo::readImage(path, back, error)) << error;
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); ++i)
        EXPECT_EQ(back.rgba[i], image.rgba[i]) << "value " << i;
    std::remove(path.c_str());
}

}  // namespace
