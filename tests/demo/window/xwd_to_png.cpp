// xwd_to_png: converts an XWD image (e.g. Xvfb's screen with -fbdir DIR: DIR/Xvfb_screen0) to an 8-bit RGB
// PNG. Handles TrueColor / DirectColor ZPixmap images of 24 or 32 bits per pixel (and 16) with the
// channel masks of the header, either byte order.
//   xwd_to_png IN.xwd OUT.png
// The XWD layout (X11/XWDFile.h): a header of 25 big-endian CARD32 fields, the window name (up to
// header_size), ncolors 12-byte XWDColor entries, then the pixels, bytes_per_line per row.
#include <OpenImageIO/imageio.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

enum Field {
    kHeaderSize,
    kFileVersion,
    kPixmapFormat,
    kPixmapDepth,
    kPixmapWidth,
    kPixmapHeight,
    kXOffset,
    kByteOrder,
    kBitmapUnit,
    kBitmapBitOrder,
    kBitmapPad,
    kBitsPerPixel,
    kBytesPerLine,
    kVisualClass,
    kRedMask,
    kGreenMask,
    kBlueMask,
    kBitsPerRgb,
    kColormapEntries,
    kNColors,
    kFieldCount = 25,
};
constexpr uint32_t kXwdVersion = 7;
constexpr uint32_t kZPixmap = 2;
constexpr uint32_t kMsbFirst = 1;
constexpr uint32_t kTrueColor = 4, kDirectColor = 5;
constexpr size_t kXwdColorSize = 12;

uint32_t be32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// A channel of `pixel` under `mask`, scaled to 0..255.
uint8_t channel(uint32_t pixel, uint32_t mask) {
    if (mask == 0) return 0;
    int shift = 0;
    while (!((mask >> shift) & 1u))
        ++shift;
    const uint32_t max = mask >> shift;
    const uint32_t v = (pixel & mask) >> shift;
    return uint8_t((v * 255u + max / 2) / max);
}

int fail(const std::string& message) {
    std::fprintf(stderr, "xwd_to_png: %s\n", message.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: xwd_to_png IN.xwd OUT.png\n");
        return 2;
    }
    const std::string inPath = argv[1], outPath = argv[2];
    std::ifstream in(inPath, std::ios::binary);
    if (!in) return fail("cannot open '" + inPath + "'");
    const std::vector<uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (data.size() < kFieldCount * 4) return fail("'" + inPath + "' is too short for an XWD header");
    std::array<uint32_t, kFieldCount> h{};
    for (size_t i = 0; i < h.size(); ++i)
        h[i] = be32(&data[i * 4]);

    if (h[kFileVersion] != kXwdVersion)
        return fail("'" + inPath + "': XWD version " + std::to_string(h[kFileVersion]) + ", expected 7");
    if (h[kPixmapFormat] != kZPixmap) return fail("only ZPixmap images are supported");
    if (h[kVisualClass] != kTrueColor && h[kVisualClass] != kDirectColor)
        return fail("only TrueColor / DirectColor visuals are supported (class " +
                    std::to_string(h[kVisualClass]) + ")");
    const uint32_t bpp = h[kBitsPerPixel];
    if (bpp != 16 && bpp != 24 && bpp != 32) return fail("unsupported bits per pixel " + std::to_string(bpp));
    const uint32_t width = h[kPixmapWidth], height = h[kPixmapHeight], stride = h[kBytesPerLine];
    const size_t bytesPerPixel = bpp / 8;
    if (width == 0 || height == 0 || stride < size_t(width) * bytesPerPixel)
        return fail("bad image size " + std::to_string(width) + "x" + std::to_string(height) + ", " +
                    std::to_string(stride) + " bytes per line");
    const size_t offset = size_t(h[kHeaderSize]) + size_t(h[kNColors]) * kXwdColorSize;
    if (offset + size_t(stride) * height > data.size())
        return fail("'" + inPath + "' is truncated: " + std::to_string(data.size()) + " bytes, need " +
                    std::to_string(offset + size_t(stride) * height));

    const bool msb = h[kByteOrder] == kMsbFirst;
    std::vector<uint8_t> rgb(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y) {
        const uint8_t* row = &data[offset + size_t(y) * stride];
        for (uint32_t x = 0; x < width; ++x) {
            const uint8_t* p = row + x * bytesPerPixel;
            uint32_t pixel = 0;
            for (size_t b = 0; b < bytesPerPixel; ++b) {
                const size_t shift = msb ? (bytesPerPixel - 1 - b) * 8 : b * 8;
                pixel |= uint32_t(p[b]) << shift;
            }
            uint8_t* o = &rgb[(size_t(y) * width + x) * 3];
            o[0] = channel(pixel, h[kRedMask]);
            o[1] = channel(pixel, h[kGreenMask]);
            o[2] = channel(pixel, h[kBlueMask]);
        }
    }

    auto out = OIIO::ImageOutput::create(outPath);
    if (!out) return fail("cannot write '" + outPath + "': " + OIIO::geterror());
    const OIIO::ImageSpec spec(int(width), int(height), 3, OIIO::TypeDesc::UINT8);
    if (!out->open(outPath, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !out->close())
        return fail("cannot write '" + outPath + "': " + out->geterror());
    std::printf("xwd_to_png: %s (%ux%u, %u bpp) -> %s\n", inPath.c_str(), width, height, bpp,
                outPath.c_str());
    return 0;
}
