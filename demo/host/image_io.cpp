// Image files of the demo: .exr (linear 32-bit float RGBA) and .png (tonemapped 8-bit sRGB), via
// OpenImageIO. Built as a module of its own, loaded on first use (image_io.h says why).
#include "host/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace demo {
namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string unknownExtension(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    return "unsupported image file extension '" + (ext.empty() ? std::string("(none)") : ext) + "' in '" +
           path + "' (expected .exr or .png)";
}

// ACES filmic curve fitted by Narkowicz (2015), input and output linear, output in [0, 1].
float acesFitted(float x) {
    x = std::max(x, 0.0f);
    return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

float srgbOetf(float x) {
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}
float srgbEotf(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

bool write(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc dataType, const void* data,
           std::string& error) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        error = "cannot write '" + path + "': " + OIIO::geterror();
        return false;
    }
    if (!out->open(path, spec) || !out->write_image(dataType, data) || !out->close()) {
        error = "cannot write '" + path + "': " + out->geterror();
        return false;
    }
    return true;
}

// `exposure`: the PNG's, from camera.ev100 (demo::exposureFromEv100, the loader computes it).
bool writeWithOiio(const std::string& path, const ImageF& image, float exposure, std::string& error) {
    const std::string ext = lowerExtension(path);
    const size_t pixels = size_t(image.width) * image.height;
    if (pixels == 0 || image.rgba.size() != pixels * 4) {
        error = "cannot write '" + path + "': the image is empty or its pixel count does not match its size";
        return false;
    }
    if (ext == ".exr") {
        // 32-bit floats: radiance in physical units (the renderer divided its pre-exposure out) exceeds
        // half's 65,504 toward a 100,000 lux sun.
        OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::FLOAT);
        spec.attribute("compression", "zip");
        return write(path, spec, OIIO::TypeDesc::FLOAT, image.rgba.data(), error);
    }
    if (ext == ".png") {
        std::vector<uint8_t> rgb(pixels * 3);
        for (size_t i = 0; i < pixels; ++i) {
            for (int c = 0; c < 3; ++c) {
                const float v = srgbOetf(acesFitted(image.rgba[i * 4 + c] * exposure));
                rgb[i * 3 + c] = uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            }
        }
        OIIO::ImageSpec spec(int(image.width), int(image.height), 3, OIIO::TypeDesc::UINT8);
        return write(path, spec, OIIO::TypeDesc::UINT8, rgb.data(), error);
    }
    error = unknownExtension(path);
    return false;
}

// .exr: linear RGBA as stored. .png: 8-bit sRGB decoded to linear display values in [0, 1] (not
// scene radiance: the tonemap is not inverted). Missing alpha reads as 1, grey as R = G = B.
bool readWithOiio(const std::string& path, ImageF& image, std::string& error) {
    const std::string ext = lowerExtension(path);
    if (ext != ".exr" && ext != ".png") {
        error = unknownExtension(path);
        return false;
    }
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        error = "cannot read '" + path + "': " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || channels <= 0) {
        error = "cannot read '" + path + "': empty image";
        return false;
    }
    std::vector<float> data(size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
        error = "cannot read '" + path + "': " + in->geterror();
        return false;
    }
    image.width = uint32_t(spec.width);
    image.height = uint32_t(spec.height);
    image.rgba.assign(size_t(spec.width) * spec.height * 4, 1.0f);
    const bool decode = ext == ".png";
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
        for (int c = 0; c < 4; ++c) {
            const int src = channels >= 3 ? c : (c < 3 ? 0 : 1);  // grey (+ alpha) -> RGB(A)
            if (src >= channels || (c == 3 && channels == 3)) continue;
            const float v = data[i * channels + src];
            image.rgba[i * 4 + c] = decode && c < 3 ? srgbEotf(v) : v;
        }
    }
    return true;
}

bool writePng8WithOiio(const std::string& path, uint32_t width, uint32_t height, uint32_t channels,
                       const std::vector<uint8_t>& pixels, std::string& error) {
    if (lowerExtension(path) != ".png") {
        error = "writePng8: '" + path + "' is not a .png";
        return false;
    }
    if (width == 0 || height == 0 || channels == 0 || channels > 4 ||
        pixels.size() != size_t(width) * height * channels) {
        error = "cannot write '" + path + "': " + std::to_string(pixels.size()) + " bytes for " +
                std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(channels);
        return false;
    }
    const OIIO::ImageSpec spec(int(width), int(height), int(channels), OIIO::TypeDesc::UINT8);
    return write(path, spec, OIIO::TypeDesc::UINT8, pixels.data(), error);
}

}  // namespace
}  // namespace demo

extern "C" __attribute__((visibility("default"))) const demo::ImageIoFunctions* postfx_demo_image_io() {
    static const demo::ImageIoFunctions functions{&demo::writeWithOiio, &demo::readWithOiio,
                                                  &demo::writePng8WithOiio};
    return &functions;
}
