// The demo's image files (demo/host/image_io.cpp): an EXR holds 32-bit float RGBA, so that radiance in
// physical units keeps its range and precision (half would clip at 65504 and round to 11 bits).
#include "host/renderer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

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

    // The file's pixel format, as OpenImageIO reads it: FLOAT in every channel.
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, 2);
    EXPECT_EQ(spec.height, 1);
    EXPECT_EQ(spec.nchannels, 4);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT) << spec.format.c_str();
    for (int c = 0; c < spec.nchannels; ++c)
        EXPECT_EQ(spec.channelformat(c), OIIO::TypeDesc::FLOAT) << spec.channel_name(c);
    in->close();

    // And every value back exactly.
    demo::ImageF back;
    ASSERT_TRUE(demo::readImage(path, back, error)) << error;
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); ++i)
        EXPECT_EQ(back.rgba[i], image.rgba[i]) << "value " << i;
    std::remove(path.c_str());
}

}  // namespace
